// Footfall — the field paths that errors name ("agents[1].position"), for
// every reader and validator alike.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace footfall::detail {

/// Throws std::invalid_argument "PATH: MESSAGE".
[[noreturn]] inline void fail(const std::string& path, const std::string& message) {
  throw std::invalid_argument(path + ": " + message);
}

/// "path.key", or "key" at the top.
inline std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

/// "path[index]".
inline std::string item(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

}  // namespace footfall::detail
