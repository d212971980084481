// Footfall — the field paths that errors name ("agents[1].position"), for
// every reader and validator alike.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "util/quoted.hpp"

namespace footfall::detail {

/// Throws std::invalid_argument "PATH: MESSAGE".
[[noreturn]] inline void fail(const std::string& path, const std::string& message) {
  throw std::invalid_argument(path + ": " + message);
}

/// "path.key", or "key" at the top; a key that is not a plain name (letters,
/// digits, '_') is quoted, so that what a file holds cannot break the message.
inline std::string child(const std::string& path, const std::string& key) {
  const bool plain = !key.empty() && key.size() <= 80 &&
                     key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789_") == std::string::npos;
  const std::string shown = plain ? key : user_text(key);
  return path.empty() ? shown : path + "." + shown;
}

/// "path[index]".
inline std::string item(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

}  // namespace footfall::detail
