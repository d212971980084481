// The animated crowd as glTF: footfall._native.animate_gltf.
#include "bindings.hpp"
#include "footfall/animate/crowd_gltf.hpp"

namespace footfall::bindings {

namespace py = pybind11;

void bind_animate(py::module_& m) {
  m.def(
      "animate_gltf",
      [](const Plan& plan, const std::string& rig_path, const std::string& out_path, double fps,
         const std::string& profile_path) {
        CrowdGltfSummary summary;
        {
          py::gil_scoped_release release;
          const Rig rig = Rig::load(
              rig_path, load_rig_profile(profile_path.empty() ? profile_beside(rig_path) : profile_path));
          CrowdGltfOptions options;
          options.fps = fps;
          summary = write_crowd_gltf(plan, rig, out_path, options);
        }
        py::dict result;
        result["agents"] = summary.agents;
        result["frames"] = summary.frames;
        result["bytes"] = summary.bytes;
        result["clips"] = summary.clips;
        return result;
      },
      py::arg("plan"), py::arg("rig_path"), py::arg("out_path"), py::arg("fps") = 24.0,
      py::arg("profile_path") = "",
      "Animates every agent of `plan` on the rig (.glb or .gltf; its profile beside it, "
      "RIG.json, unless `profile_path` is given) and writes one animated .glb to `out_path`, "
      "`fps` keys a second. Returns {agents, frames, bytes, clips}. ValueError names what is "
      "wrong (the rig, its profile, an agent planned for another size); no file is left then.");
}

}  // namespace footfall::bindings
