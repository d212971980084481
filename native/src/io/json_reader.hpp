// Private: reading JSON with errors that name the field path, shared by the
// scenario and plan readers.
#pragma once

#include <initializer_list>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "footfall/model/geometry.hpp"
#include "util/field_path.hpp"

namespace footfall::detail {

using Json = nlohmann::json;

/// Parses `text`; a syntax error becomes std::invalid_argument "SOURCE: not
/// valid JSON: ... line L, column C ...".
Json parse_json(const std::string& text, const std::string& source);

/// Reads the whole file; std::invalid_argument naming it if it cannot.
std::string read_file(const std::string& path);

/// The JSON type's name, for messages ("string", "array", ...).
std::string type_name(const Json& value);

/// `value` must be an object whose keys are all in `allowed`.
void expect_object(const Json& value, const std::string& path,
                   std::initializer_list<const char*> allowed);
/// The member `key` of an object, which must be present.
const Json& require(const Json& object, const std::string& path, const char* key);
/// A finite number (not a boolean).
double number(const Json& value, const std::string& path);
/// An integer.
long long integer(const Json& value, const std::string& path);
/// true or false.
bool boolean(const Json& value, const std::string& path);
/// A string.
std::string string(const Json& value, const std::string& path);
/// An array (any length).
const Json& array(const Json& value, const std::string& path);
/// A point [x, y] of two finite numbers.
Vec2 point(const Json& value, const std::string& path);
/// A point [x, y] or [x, y, z] of finite numbers: the point and its height, if given.
std::pair<Vec2, std::optional<double>> point_and_height(const Json& value,
                                                        const std::string& path);

/// A point as JSON [x, y].
Json to_json(Vec2 point);

/// Checks "format" and "version" of a Footfall file.
void expect_header(const Json& root, const char* format, int version);

}  // namespace footfall::detail
