#include "io/json_writer.hpp"

#include <charconv>
#include <cmath>

namespace footfall::detail {

namespace {

constexpr std::size_t kBufferSize = 1 << 16;

}  // namespace

void JsonWriter::separate() {
  if (after_key_) {
    after_key_ = false;
  } else if (!first_.empty()) {
    if (!first_.back()) put(",");
    first_.back() = false;
  }
}

void JsonWriter::put(std::string_view text) {
  buffer_ += text;
  if (buffer_.size() >= kBufferSize) flush();
}

JsonWriter& JsonWriter::begin_object() { return open("{"); }

JsonWriter& JsonWriter::end_object() { return close("}"); }

JsonWriter& JsonWriter::begin_array() { return open("["); }

JsonWriter& JsonWriter::end_array() { return close("]"); }

JsonWriter& JsonWriter::open(std::string_view bracket) {
  separate();
  put(bracket);
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::close(std::string_view bracket) {
  first_.pop_back();
  put(bracket);
  return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  string(name);
  put(":");
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::number(double value) {
  separate();
  if (!std::isfinite(value)) {
    put("null");
    return *this;
  }
  char text[32];
  const char* end = std::to_chars(text, text + sizeof text, value).ptr;
  put(std::string_view(text, static_cast<std::size_t>(end - text)));
  if (value == 0.0 && std::signbit(value)) put(".0");  // "-0" reads back as the integer 0
  return *this;
}

JsonWriter& JsonWriter::integer(long long value) {
  separate();
  char text[24];
  const char* end = std::to_chars(text, text + sizeof text, value).ptr;
  put(std::string_view(text, static_cast<std::size_t>(end - text)));
  return *this;
}

JsonWriter& JsonWriter::string(std::string_view text) {
  separate();
  put(Json(std::string(text)).dump());
  return *this;
}

JsonWriter& JsonWriter::value(const Json& json) {
  if (json.is_object()) {
    begin_object();
    for (auto it = json.begin(); it != json.end(); ++it) key(it.key()).value(*it);
    return end_object();
  }
  if (json.is_array()) {
    begin_array();
    for (const Json& element : json) value(element);
    return end_array();
  }
  if (json.is_number_float()) return number(json.get<double>());
  separate();
  put(json.dump());
  return *this;
}

void JsonWriter::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

}  // namespace footfall::detail
