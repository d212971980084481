#include "animate_command.hpp"

#include <chrono>
#include <filesystem>
#include <iomanip>

#include "footfall/animate/crowd_gltf.hpp"
#include "util/quoted.hpp"

namespace footfall::tools {

void animate_and_write(const Plan& plan, const AnimateArguments& arguments, const std::string& output,
                       std::ostream& out) {
  const auto begin = std::chrono::steady_clock::now();
  const Rig rig = Rig::load(arguments.rig, rig_profile_for(arguments.rig, arguments.profile));
  const std::filesystem::path folder = std::filesystem::path(output).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder);
  CrowdGltfOptions options;
  options.fps = arguments.fps;
  const CrowdGltfSummary summary = write_crowd_gltf(plan, rig, output, options);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  out << "clips:";
  for (const auto& [behavior, source] : summary.clips) out << " " << behavior << " = " << detail::user_text(source) << ";";
  out << "\n" << std::fixed << std::setprecision(2) << summary.agents << " agents x " << summary.frames
      << " frames at " << arguments.fps << " fps, " << static_cast<double>(summary.bytes) / 1e6
      << " MB, written in " << wall << " s to " << output << "\n";
}

}  // namespace footfall::tools
