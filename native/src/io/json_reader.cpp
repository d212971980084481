#include "io/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "util/quoted.hpp"

namespace footfall::detail {

namespace {

// Python's json module writes NaN, Infinity and -Infinity as bare tokens, which
// JSON forbids, and a number too large for a double (1e400) stops the JSON
// parser with no field to name. Both are turned into marker strings so that
// number() can name the field that holds them.
constexpr const char* kNonFiniteMarker = "\x01non-finite:";

// The length of the JSON number at text[i] (0 if none starts there), and
// whether it is too large for a double.
std::pair<size_t, bool> number_at(const std::string& text, size_t i) {
  const char c = text[i];
  if (c != '-' && (c < '0' || c > '9')) return {0, false};
  size_t n = 0;
  bool exponent = false;
  // (strchr finds the terminator too: a NUL in the text ends the number.)
  for (; i + n < text.size() && text[i + n] != '\0' &&
         std::strchr("+-0123456789.eE", text[i + n]) != nullptr;
       ++n)
    exponent = exponent || text[i + n] == 'e' || text[i + n] == 'E';
  // Without an exponent, only 309 digits or more overflow: most numbers need no strtod.
  if (!exponent && n < 309) return {n, false};
  return {n, std::isinf(std::strtod(text.c_str() + i, nullptr))};
}

// A marker for `token` as written, cut short if long (a 400-digit number).
std::string marker_of(const std::string& token) {
  const std::string shown = token.size() > 24 ? token.substr(0, 20) + "..." : token;
  return std::string("\"") + "\\u0001non-finite:" + shown + "\"";
}

// Returns the text with the tokens replaced; `shifts` gets, for each
// replacement, where it ends in the new text and how many characters it added.
std::string mark_non_finite(const std::string& text,
                            std::vector<std::pair<size_t, size_t>>& shifts) {
  std::string out;
  out.reserve(text.size());
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size()) {
        out += text[++i];
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') in_string = true;
    size_t n = 0;
    for (const char* token : {"NaN", "Infinity", "-Infinity"}) {
      if (text.compare(i, std::char_traits<char>::length(token), token) == 0)
        n = std::char_traits<char>::length(token);
    }
    if (n == 0) {
      const auto [length, too_large] = number_at(text, i);
      if (!too_large) {
        // Not a marker: the number is copied whole (its digits cannot start a token).
        out.append(text, i, std::max<size_t>(length, 1));
        i += std::max<size_t>(length, 1) - 1;
        continue;
      }
      n = length;
    }
    const std::string marker = marker_of(text.substr(i, n));
    out += marker;
    shifts.emplace_back(out.size(), marker.size() - n);
    i += n - 1;
  }
  return out;
}

// "line L, column C" of byte `byte` (1-based, as the parser counts) of `text`.
std::string position_in(const std::string& text, size_t byte) {
  size_t line = 1, line_start = 0;
  for (size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(byte - line_start);
}

}  // namespace

Json parse_json(const std::string& text, const std::string& source) {
  std::vector<std::pair<size_t, size_t>> shifts;
  try {
    return Json::parse(mark_non_finite(text, shifts));
  } catch (const Json::parse_error& error) {
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix.
    std::string message = error.what();
    const size_t bracket = message.find("] ");
    if (message.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) {
      message = message.substr(bracket + 2);
    }
    // Report the position in the text as written, before the markers.
    size_t byte = error.byte;
    for (const auto& [end, added] : shifts) {
      if (end < error.byte) byte -= added;
    }
    const size_t at = message.find("line ");
    const size_t colon = message.find(':', at);
    if (!shifts.empty() && at != std::string::npos && colon != std::string::npos) {
      message = message.substr(0, at) + position_in(text, byte) + message.substr(colon);
    }
    throw std::invalid_argument(source + ": not valid JSON: " + message);
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(path + ": cannot open the file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string type_name(const Json& value) {
  if (value.is_number()) return "number";
  return value.type_name();
}

void expect_object(const Json& value, const std::string& path,
                   std::initializer_list<const char*> allowed) {
  if (!value.is_object())
    fail(path.empty() ? "(top level)" : path, "expected an object, got " + type_name(value));
  for (auto it = value.begin(); it != value.end(); ++it) {
    bool known = false;
    for (const char* key : allowed) known = known || it.key() == key;
    if (!known) fail(child(path, it.key()), "unknown field");
  }
}

const Json& require(const Json& object, const std::string& path, const char* key) {
  const auto it = object.find(key);
  if (it == object.end()) fail(child(path, key), "missing");
  return *it;
}

double number(const Json& value, const std::string& path) {
  if (value.is_string()) {
    const std::string& text = value.get_ref<const std::string&>();
    if (text.rfind(kNonFiniteMarker, 0) == 0) {
      fail(path, "must be a finite number, got " +
                     text.substr(std::char_traits<char>::length(kNonFiniteMarker)));
    }
  }
  if (!value.is_number()) fail(path, "expected a number, got " + type_name(value));
  const double v = value.get<double>();
  if (!std::isfinite(v)) fail(path, "must be a finite number");
  return v;
}

long long integer(const Json& value, const std::string& path) {
  if (!value.is_number_integer()) fail(path, "expected an integer, got " + type_name(value));
  if (value.is_number_unsigned() && value.get<unsigned long long>() > 9223372036854775807ull) {
    fail(path, "too large");
  }
  return value.get<long long>();
}

bool boolean(const Json& value, const std::string& path) {
  if (!value.is_boolean()) fail(path, "expected true or false, got " + type_name(value));
  return value.get<bool>();
}

std::string string(const Json& value, const std::string& path) {
  if (!value.is_string()) fail(path, "expected a string, got " + type_name(value));
  return value.get<std::string>();
}

const Json& array(const Json& value, const std::string& path) {
  if (!value.is_array()) fail(path, "expected an array, got " + type_name(value));
  return value;
}

Vec2 point(const Json& value, const std::string& path) {
  if (!value.is_array() || value.size() != 2) fail(path, "expected a point [x, y]");
  return {number(value[0], item(path, 0)), number(value[1], item(path, 1))};
}

std::pair<Vec2, std::optional<double>> point_and_height(const Json& value,
                                                        const std::string& path) {
  if (!value.is_array() || (value.size() != 2 && value.size() != 3))
    fail(path, "expected a point [x, y] or [x, y, z]");
  const Vec2 p{number(value[0], item(path, 0)), number(value[1], item(path, 1))};
  if (value.size() == 2) return {p, std::nullopt};
  return {p, number(value[2], item(path, 2))};
}

Json to_json(Vec2 p) { return Json::array({p.x, p.y}); }

void expect_header(const Json& root, const char* format, int version) {
  if (!root.is_object()) fail("(top level)", "expected an object, got " + type_name(root));
  const std::string found = string(require(root, "", "format"), "format");
  if (found != format)
    fail("format", std::string("expected \"") + format + "\", got " + user_text(found));
  const long long v = integer(require(root, "", "version"), "version");
  if (v != version) {
    fail("version", "unsupported version " + std::to_string(v) + " (this Footfall reads version " +
                        std::to_string(version) + ")");
  }
}

}  // namespace footfall::detail
