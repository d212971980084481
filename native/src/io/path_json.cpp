// Footfall — path results as JSON.
#include "footfall/io/path_json.hpp"

#include <nlohmann/json.hpp>

namespace footfall {

namespace {

nlohmann::json points_json(const std::vector<Vec2>& points, std::size_t skip = 0) {
  nlohmann::json json = nlohmann::json::array();
  for (std::size_t k = skip; k < points.size(); ++k) json.push_back({points[k].x, points[k].y});
  return json;
}

}  // namespace

std::string to_json(const PathResult& result) {
  nlohmann::json points = points_json(result.points);
  for (std::size_t k = 0; k < result.heights.size() && k < points.size(); ++k)
    points[k].push_back(result.heights[k]);
  return nlohmann::ordered_json{{"status", to_string(result.status)},
                        {"points", points},
                        {"length", result.length},
                        {"min_clearance", result.min_clearance}}
      .dump();
}


std::string to_json(const BehaviorPath& path) {
  nlohmann::json points = nlohmann::json::array();
  nlohmann::ordered_json sections = nlohmann::ordered_json::array();
  for (const BehaviorSection& section : path.sections) {
    // Sections join end to end: each after the first adds its points but the first.
    for (auto& p : points_json(section.points, points.empty() ? 0 : 1)) points.push_back(p);
    sections.push_back(nlohmann::ordered_json{{"behavior", to_string(section.behavior)},
                                              {"clearance", section.clearance},
                                              {"points", points_json(section.points)},
                                              {"length", section.length}});
  }
  nlohmann::ordered_json json{{"status", to_string(path.status)},
                              {"points", points},
                              {"length", path.length},
                              {"min_clearance", path.min_clearance},
                              {"sections", sections},
                              {"point_obstacles", path.point_obstacles},
                              {"poses_tested", path.poses_tested}};
  if (!path.reason.empty()) json["reason"] = path.reason;
  return json.dump();
}

}  // namespace footfall
