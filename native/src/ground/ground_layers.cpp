// Footfall — the ground split into layers with one level over any point (a
// street and a bridge's deck over it), each with its walls, and the portals
// where one layer's ground meets another's within a step.
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "footfall/ground/ground.hpp"
#include "ground/walkable_edges.hpp"

namespace footfall {
namespace {

/// What a sample of an edge is for one layer: a wall of it (to = -1), or a
/// portal from it, on the edge's side, to the layer `to` across.
using Run = std::pair<int, int>;

const GroundPoint* first_on(const std::vector<GroundPoint>& levels, const GroundLayers& layers,
                            int layer) {
  for (const GroundPoint& level : levels)
    if (layers.layer_of(level) == layer) return &level;
  return nullptr;
}

/// The runs a sample belongs to, between `inner` (the edge's side) and `outer`.
std::vector<Run> runs_at(const std::vector<GroundPoint>& inner,
                         const std::vector<GroundPoint>& outer, const GroundLayers& layers,
                         double max_step) {
  std::vector<int> present;
  for (const auto* side : {&inner, &outer})
    for (const GroundPoint& level : *side) present.push_back(layers.layer_of(level));
  std::sort(present.begin(), present.end());
  present.erase(std::unique(present.begin(), present.end()), present.end());
  std::vector<Run> runs;
  for (const int layer : present) {
    const GroundPoint* in = first_on(inner, layers, layer);
    const GroundPoint* out = first_on(outer, layers, layer);
    if (in != nullptr && out != nullptr && std::fabs(in->z - out->z) <= max_step) continue;
    runs.push_back({layer, -1});
    if (in == nullptr) continue;
    for (const GroundPoint& across : outer) {
      const int to = layers.layer_of(across);
      if (to != layer && std::fabs(across.z - in->z) <= max_step &&
          std::find(runs.begin(), runs.end(), Run{layer, to}) == runs.end())
        runs.push_back({layer, to});
    }
  }
  return runs;
}

/// Adds `portal` unless it is there already (found along another face's edge
/// that runs along the same line: a street's edge under a deck's).
void add_portal(std::vector<GroundPortal>& portals, const GroundPortal& portal) {
  constexpr double kSame = 0.01;  // [m]
  const auto same = [&](const GroundPortal& other) {
    return other.from == portal.from && other.to == portal.to &&
           ((distance(other.a, portal.a) <= kSame && distance(other.b, portal.b) <= kSame) ||
            (distance(other.a, portal.b) <= kSame && distance(other.b, portal.a) <= kSame));
  };
  if (std::none_of(portals.begin(), portals.end(), same)) portals.push_back(portal);
}

}  // namespace

std::optional<GroundPoint> GroundLayers::level_on(Vec2 p, int layer) const {
  const std::vector<GroundPoint> levels = ground_->standable_at(p, headroom_);
  if (const GroundPoint* level = first_on(levels, *this, layer)) return *level;
  return std::nullopt;
}

GroundLayers Ground::layers(double max_step, double headroom, double min_normal_z) const {
  GroundLayers layers;
  layers.ground_ = this;
  layers.headroom_ = headroom;
  // Per face, the faces standable over one point with it.
  std::vector<std::vector<int>> apart(faces_.size());
  bool stacked = false;
  visit_inner_edge_samples([&](Vec2 p) {
    const std::vector<GroundPoint> levels = standable_at(p, headroom);
    for (std::size_t i = 0; i < levels.size(); ++i)
      for (std::size_t j = i + 1; j < levels.size(); ++j) {
        stacked = true;
        for (const auto& [f, g] : {std::pair{levels[i].face, levels[j].face},
                                   std::pair{levels[j].face, levels[i].face}})
          if (std::find(apart[f].begin(), apart[f].end(), g) == apart[f].end())
            apart[f].push_back(g);
      }
  });
  if (!stacked) {
    layers.walls_.push_back(walls(max_step, headroom, min_normal_z));
    return layers;
  }
  std::vector<int>& layer_of = layers.face_layer_;
  layer_of.assign(faces_.size(), -1);
  int count = 0;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (!faces_[f].walkable) continue;
    std::vector<bool> taken(count + 1, false);
    for (const int g : apart[f])
      if (layer_of[g] >= 0) taken[layer_of[g]] = true;
    const int layer =
        static_cast<int>(std::find(taken.begin(), taken.end(), false) - taken.begin());
    if (layer >= GroundLayers::kMaxLayers)
      throw std::invalid_argument("ground: more than " + std::to_string(GroundLayers::kMaxLayers) +
                                  " levels above one another");
    layer_of[f] = layer;
    count = std::max(count, layer + 1);
  }
  layers.walls_.resize(count);
  visit_walkable_edges(
      [&](Vec2 a, Vec2 b, double, double, Vec2 outward) {
        const int samples =
            std::max(1, static_cast<int>(std::ceil(length(b - a) / kEdgeSpacing)));
        const auto at = [&](int i) { return a + (static_cast<double>(i) / samples) * (b - a); };
        std::map<Run, int> open;  // each open run's first sample
        for (int i = 0; i <= samples; ++i) {
          std::vector<Run> here;
          if (i < samples) {
            const Vec2 s = a + ((i + 0.5) / samples) * (b - a);
            const auto standable = [&](Vec2 p) {
              return not_too_steep(standable_at(p, headroom), min_normal_z);
            };
            here = runs_at(standable(s - kEdgeBeside * outward),
                           standable(s + kEdgeBeside * outward), layers, max_step);
          }
          for (auto run = open.begin(); run != open.end();) {
            if (std::find(here.begin(), here.end(), run->first) != here.end()) {
              ++run;
              continue;
            }
            const auto [layer, to] = run->first;
            if (to < 0)
              layers.walls_[layer].push_back({at(run->second), at(i)});
            else
              add_portal(layers.portals_, {at(run->second), at(i), layer, to, outward});
            run = open.erase(run);
          }
          for (const Run& run : here) open.emplace(run, i);
        }
      },
      [&](int f, int g) {
        const auto steep = [&](int face) { return faces_[face].normal.z < min_normal_z; };
        return layer_of[f] != layer_of[g] || steep(f) != steep(g);
      });
  return layers;
}

}  // namespace footfall
