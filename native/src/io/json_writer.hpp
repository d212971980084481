// Private: JSON written as it goes to a stream, compact, each number in the
// shortest form that reads back as the same double. The plan file's writer:
// a plan of a large crowd is never held whole in memory as text or as a tree.
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "io/json_reader.hpp"

namespace footfall::detail {

/// Writes one JSON value to a stream, through a buffer of some 64 KiB. The
/// commas between items and members are its own; keys and values are the
/// caller's to put in a valid order. Stream failures are the stream's state.
class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  /// The key of the next member of the object begun last.
  JsonWriter& key(std::string_view name);
  /// The shortest text that reads back as `value` to the bit (std::to_chars;
  /// -0 as "-0.0", which reads back negative); null if it is not finite, as
  /// nlohmann::json writes it.
  JsonWriter& number(double value);
  JsonWriter& integer(long long value);
  /// A string, escaped as nlohmann::json escapes it (invalid UTF-8 throws its type_error).
  JsonWriter& string(std::string_view text);
  /// A small tree as it is, its floating-point numbers as number() writes them.
  JsonWriter& value(const Json& json);
  /// Passes what is buffered on to the stream; call it at the end.
  void flush();

 private:
  /// The comma before an item or member that is not its container's first.
  void separate();
  void put(std::string_view text);
  /// Opens or closes an object or array (`bracket`), keeping `first_`.
  JsonWriter& open(std::string_view bracket);
  JsonWriter& close(std::string_view bracket);

  std::ostream& out_;
  std::string buffer_;
  std::vector<bool> first_;  ///< Per open container: nothing written in it yet.
  bool after_key_ = false;   ///< A key was written: its value comes without a comma.
};

}  // namespace footfall::detail
