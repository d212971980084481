#include "io/atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "footfall/model/status.hpp"
#include "util/pending_files.hpp"
#include "util/quoted.hpp"

namespace footfall::detail {

namespace {

// The file written before it is renamed into place: hidden, beside the
// target, unique to the process and the write, so that two runs
// writing one file at once do not share it ("PLAN.json" ->
// ".PLAN.json.<pid>-<n>.partial").
std::string temporary_name(const std::string& path) {
  static std::atomic<unsigned> writes{0};
  const std::filesystem::path target(path);
  return (target.parent_path() / ("." + target.filename().string() + "." +
                                  std::to_string(::getpid()) + "-" +
                                  std::to_string(writes++) + ".partial"))
      .string();
}

// Removes the temporaries of `path` that a run stopped before it finished
// (killed, say) left behind: those of processes no longer running.
void remove_stale_temporaries(const std::string& path) {
  const std::filesystem::path target(path);
  const std::string prefix = "." + target.filename().string() + ".";
  const std::filesystem::path folder =
      target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() + 8 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 8, 8, ".partial") != 0)
      continue;
    const std::string pid =
        name.substr(prefix.size(), name.find('-', prefix.size()) - prefix.size());
    if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos)
      continue;
    if (::kill(static_cast<pid_t>(std::stol(pid)), 0) == -1 && errno == ESRCH)
      std::filesystem::remove(entry.path(), error);
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& bytes) {
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  if (path.find('\0') != std::string::npos)
    throw std::invalid_argument(user_text(path) + ": a file name cannot hold a NUL byte");
  remove_stale_temporaries(path);
  const std::string temporary = temporary_name(path);
  note_pending_file(temporary);
  const auto remove_temporary = [&] {
    std::remove(temporary.c_str());
    forget_pending_file(temporary);
  };
  const auto fail_with = [&](const std::string& message) {
    remove_temporary();
    throw Error(path + ": " + message);
  };
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) fail_with("cannot open for writing");
    try {
      write(out);
    } catch (...) {
      out.close();
      remove_temporary();
      throw;
    }
    out.flush();
    if (!out) fail_with("write failed");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    fail_with("cannot move the finished file into place");
  forget_pending_file(temporary);
}

}  // namespace footfall::detail
