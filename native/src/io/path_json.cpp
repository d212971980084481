// Footfall — path results as JSON.
#include "footfall/io/path_json.hpp"

#include <nlohmann/json.hpp>

namespace footfall {

std::string to_json(const PathResult& result) {
  nlohmann::json points = nlohmann::json::array();
  for (Vec2 p : result.points) points.push_back({p.x, p.y});
  return nlohmann::ordered_json{{"status", to_string(result.status)},
                        {"points", points},
                        {"length", result.length},
                        {"min_clearance", result.min_clearance}}
      .dump();
}

}  // namespace footfall
