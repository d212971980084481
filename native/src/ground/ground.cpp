#include "footfall/ground/ground.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace footfall {
namespace {

constexpr double kFirstCell = 0.5;  // [m] about two soles: treads, a height field's triangles
constexpr double kLevelRatio = 4.0;
constexpr double kMostCells = 16;  // a face's cells in the index
constexpr double kMaxHeight = 1000.0;  // [m] as obstacles' heights
constexpr double kMinNormalZ = 1e-9;   // a face steeper than this stands on edge: no footprint
constexpr int kSoleRows = 7, kSoleColumns = 4;  // the sole's sample grid
constexpr int kSoleSamples = kSoleRows * kSoleColumns;
constexpr double kInstep = 0.1;  // [m] above the sole: ground there is ground the foot is in
constexpr double kToeRoom = 0.01;  // [m] kept from a riser before the toe and behind the heel

[[noreturn]] void refuse(const std::string& field, const std::string& what) {
  throw std::invalid_argument(field + ": " + what);
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void validate_prism(const GroundSurface& prism, const std::string& name) {
  if (prism.polygon.size() < 3)
    refuse(name + ".polygon",
           "needs at least 3 points, got " + std::to_string(prism.polygon.size()));
  for (std::size_t k = 0; k < prism.polygon.size(); ++k)
    if (!in_world(prism.polygon[k]))
      refuse(name + ".polygon[" + std::to_string(k) + "]",
             "coordinates must be finite numbers within 1e9 m of the origin");
  if (!(std::isfinite(prism.height) && std::fabs(prism.height) <= kMaxHeight))
    refuse(name + ".height", "must be in [-1000, 1000] m, got " + number_text(prism.height));
  if (!(std::isfinite(prism.base) && prism.base >= -kMaxHeight && prism.base <= prism.height))
    refuse(name + ".base", "must be in [-1000, height] = [-1000, " + number_text(prism.height) +
                               "] m, got " + number_text(prism.base));
}

std::uint64_t cell_key(std::int64_t ix, std::int64_t iy) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32 |
         static_cast<std::uint32_t>(iy);
}

double distance_to_outline(const std::vector<Vec2>& polygon, Vec2 p) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    nearest = std::min(nearest, distance_to_segment(p, polygon[j], polygon[i]));
  return nearest;
}

// True if every turn along the polygon goes the same way and they add up to
// one full turn (a pentagram turns one way too, twice round).
bool is_convex(const std::vector<Vec2>& polygon) {
  bool left = false, right = false;
  double turning = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()],
               c = polygon[(i + 2) % polygon.size()];
    const double turn = cross(b - a, c - b);
    left = left || turn > 0.0;
    right = right || turn < 0.0;
    turning += std::atan2(turn, dot(b - a, c - b));
  }
  return !(left && right) && std::fabs(std::fabs(turning) - 2.0 * kPi) < 1e-6;
}

}  // namespace

GroundSurface ground_prism(std::vector<Vec2> polygon, double height) {
  return prism(std::move(polygon), height, std::min(0.0, height));
}

Ground::Ground(std::vector<GroundSurface> surfaces) : surfaces_(std::move(surfaces)) {
  std::size_t triangles = 0;
  for (std::size_t i = 0; i < surfaces_.size(); ++i) {
    const std::string name = "ground[" + std::to_string(i) + "]";
    if (surfaces_[i].is_mesh()) {
      validate(surfaces_[i], name);
      triangles += surfaces_[i].mesh.triangles.size();
    } else {
      validate_prism(surfaces_[i], name);
    }
  }
  if (triangles > kMaxTriangles)
    refuse("ground", std::to_string(triangles) + " triangles in all meshes, at most " +
                         std::to_string(kMaxTriangles));
  convex_.resize(surfaces_.size(), false);
  for (std::size_t i = 0; i < surfaces_.size(); ++i) {
    const GroundSurface& surface = surfaces_[i];
    const int index = static_cast<int>(i);
    if (!surface.is_mesh()) {
      convex_[i] = is_convex(surface.polygon);
      Vec2 low = surface.polygon[0], high = low;
      for (const Vec2 p : surface.polygon) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
      }
      add_face({index, -1, {0, 0, 1}, surface.height, true}, low, high);
      continue;
    }
    const std::vector<Vec3>& v = surface.mesh.vertices;
    for (std::size_t t = 0; t < surface.mesh.triangles.size(); ++t) {
      const auto& [i0, i1, i2] = surface.mesh.triangles[t];
      const Vec3 n = cross(v[i1] - v[i0], v[i2] - v[i0]);
      const double size = length(n);
      if (!(size > 0.0) || std::fabs(n.z) <= kMinNormalZ * size) continue;  // on edge, no area
      const Vec3 normal = (1.0 / size) * n;
      const Vec2 low{std::min({v[i0].x, v[i1].x, v[i2].x}), std::min({v[i0].y, v[i1].y, v[i2].y})};
      const Vec2 high{std::max({v[i0].x, v[i1].x, v[i2].x}), std::max({v[i0].y, v[i1].y, v[i2].y})};
      add_face({index, static_cast<int>(t), normal, dot(normal, v[i0]), normal.z > 0.0}, low, high);
    }
  }
}

void Ground::add_face(Face face, Vec2 low, Vec2 high) {
  const int id = static_cast<int>(faces_.size());
  face.box = {low, high};
  faces_.push_back(face);
  walkable_faces_ += face.walkable ? 1 : 0;
  // The first level on whose cells the box spans at most kMostCells (a
  // tread 3 m wide lies on 0.5 m cells, few to a cell).
  const auto spanned = [&](double cell) {
    const auto count = [&](double lo, double hi) {
      return std::floor(hi / cell) - std::floor(lo / cell) + 1;
    };
    return count(low.x, high.x) * count(low.y, high.y);
  };
  std::size_t level = 0;
  double cell = kFirstCell;
  while (spanned(cell) > kMostCells) {
    cell *= kLevelRatio;
    ++level;
  }
  while (index_.size() <= level)
    index_.push_back({kFirstCell * std::pow(kLevelRatio, static_cast<double>(index_.size())), {}});
  IndexLevel& at = index_[level];
  const auto first = [&](double x) { return static_cast<std::int64_t>(std::floor(x / at.cell)); };
  for (std::int64_t ix = first(low.x); ix <= first(high.x); ++ix)
    for (std::int64_t iy = first(low.y); iy <= first(high.y); ++iy)
      at.cells[cell_key(ix, iy)].push_back(id);
}

bool Ground::contains(const Face& face, Vec2 p) const {
  const GroundSurface& surface = surfaces_[face.surface];
  if (face.triangle < 0) return inside_even_odd(surface.polygon, p);
  const auto& [i0, i1, i2] = surface.mesh.triangles[face.triangle];
  const Vec2 a = ground(surface.mesh.vertices[i0]), b = ground(surface.mesh.vertices[i1]),
             c = ground(surface.mesh.vertices[i2]);
  // Upward faces wind counter-clockwise seen from above, downward ones
  // clockwise; edges count as inside.
  const double side = face.normal.z > 0.0 ? 1.0 : -1.0;
  return side * cross(b - a, p - a) >= 0.0 && side * cross(c - b, p - b) >= 0.0 &&
         side * cross(a - c, p - c) >= 0.0;
}

bool Ground::covers(const Face& face, Vec2 p, double z, double top) const {
  if (face.triangle < 0) {
    const GroundSurface& prism = surfaces_[face.surface];
    return prism.height > z && prism.base < top;
  }
  const double h = height_of(face, p);
  return h > z && h <= top;
}

double Ground::height_of(const Face& face, Vec2 p) const {
  return (face.d - face.normal.x * p.x - face.normal.y * p.y) / face.normal.z;
}

template <class Visit>
void Ground::visit_faces_at(Vec2 p, Visit&& visit) const {
  for (const IndexLevel& level : index_) {
    const auto cell =
        level.cells.find(cell_key(static_cast<std::int64_t>(std::floor(p.x / level.cell)),
                                  static_cast<std::int64_t>(std::floor(p.y / level.cell))));
    if (cell == level.cells.end()) continue;
    for (const int id : cell->second)
      if (in_box(faces_[id], p) && contains(faces_[id], p)) visit(faces_[id]);
  }
}

std::vector<GroundPoint> Ground::levels_at(Vec2 p) const {
  thread_local std::vector<const Face*> here;
  here.clear();
  visit_faces_at(p, [&](const Face& face) { here.push_back(&face); });
  return levels_of(here, p);
}

std::vector<GroundPoint> Ground::levels_of(const std::vector<const Face*>& here, Vec2 p) const {
  std::vector<GroundPoint> all;
  for (const Face* face : here)
    if (face->walkable)
      all.push_back({height_of(*face, p), face->normal, face->surface,
                     static_cast<int>(face - faces_.data())});
  std::sort(all.begin(), all.end(),
            [](const GroundPoint& a, const GroundPoint& b) { return a.z < b.z; });
  std::vector<GroundPoint> levels;
  for (const GroundPoint& point : all)
    if (levels.empty() || point.z - levels.back().z > kSameLevel) levels.push_back(point);
  return levels;
}

std::vector<GroundPoint> Ground::standable_at(Vec2 p, double headroom) const {
  thread_local std::vector<const Face*> here;
  here.clear();
  visit_faces_at(p, [&](const Face& face) { here.push_back(&face); });
  std::vector<GroundPoint> levels = levels_of(here, p);
  const auto covered = [&](const GroundPoint& level) {
    return std::any_of(here.begin(), here.end(), [&](const Face* face) {
      return covers(*face, p, level.z + kSameLevel, level.z + headroom);
    });
  };
  levels.erase(std::remove_if(levels.begin(), levels.end(), covered), levels.end());
  return levels;
}

std::optional<GroundPoint> Ground::standing_on(Vec2 p, double headroom) const {
  const std::vector<GroundPoint> levels = standable_at(p, headroom);
  if (levels.empty()) return std::nullopt;
  return levels.front();
}

std::optional<GroundPoint> Ground::standable_near(Vec2 p, double z, double headroom) const {
  std::optional<GroundPoint> nearest;
  for (const GroundPoint& level : standable_at(p, headroom))
    if (!nearest || std::fabs(level.z - z) < std::fabs(nearest->z - z)) nearest = level;
  return nearest;
}

std::optional<GroundPoint> Ground::level_near(Vec2 p, double z, double reach) const {
  std::optional<GroundPoint> nearest;
  visit_faces_at(p, [&](const Face& face) {
    const double h = height_of(face, p);
    if (face.walkable && std::fabs(h - z) <= reach &&
        (!nearest || std::fabs(h - z) < std::fabs(nearest->z - z)))
      nearest = GroundPoint{h, face.normal, face.surface, static_cast<int>(&face - faces_.data())};
  });
  return nearest;
}

double Ground::support(const Sole& sole, double tolerance, double min_normal_z) const {
  return static_cast<double>(soles_samples_held(sole, tolerance, min_normal_z, kSoleSamples)) /
         kSoleSamples;
}

bool Ground::holds(const Sole& sole, double tolerance, double min_normal_z, double share) const {
  const int may_miss = static_cast<int>(std::floor((1.0 - share) * kSoleSamples + 1e-9));
  return soles_samples_held(sole, tolerance, min_normal_z, may_miss) >= kSoleSamples - may_miss;
}

int Ground::soles_samples_held(const Sole& sole, double tolerance, double min_normal_z,
                               int may_miss) const {
  const Vec2 along = unit(sole.heading), across = perp(along);
  const Vec2 centre = ground(sole.centre);
  const double reach = 0.5 * std::hypot(sole.length + 2 * kToeRoom, sole.width);
  // The faces near the sole and its room, gathered once from the cells under its circle.
  thread_local std::vector<const Face*> near;
  near.clear();
  const Box circle{{centre.x - reach, centre.y - reach}, {centre.x + reach, centre.y + reach}};
  for (const IndexLevel& level : index_) {
    const auto first = [&](double v) {
      return static_cast<std::int64_t>(std::floor(v / level.cell));
    };
    for (std::int64_t ix = first(circle.min.x); ix <= first(circle.max.x); ++ix)
      for (std::int64_t iy = first(circle.min.y); iy <= first(circle.max.y); ++iy) {
        const auto cell = level.cells.find(cell_key(ix, iy));
        if (cell == level.cells.end()) continue;
        for (const int id : cell->second) {
          const Face* face = &faces_[id];
          if (face->box.min.x <= circle.max.x && face->box.max.x >= circle.min.x &&
              face->box.min.y <= circle.max.y && face->box.max.y >= circle.min.y &&
              std::find(near.begin(), near.end(), face) == near.end())
            near.push_back(face);
        }
      }
  }
  // Most soles stand inside one floor or tread with nothing else near: the
  // whole sole is held if a flat top at its height holds the circle round
  // it, or (a convex top) its four corners.
  if (near.size() == 1 && near.front()->triangle < 0 && sole.normal.x == 0.0 &&
      sole.normal.y == 0.0 && std::fabs(near.front()->d - sole.centre.z) <= tolerance) {
    const int surface = near.front()->surface;
    const std::vector<Vec2>& top = surfaces_[surface].polygon;
    const Vec2 half_along = 0.5 * sole.length * along, half_across = 0.5 * sole.width * across;
    if (distance_to_outline(top, centre) >= reach ||
        (convex_[surface] && inside_even_odd(top, centre + half_along + half_across) &&
         inside_even_odd(top, centre + half_along - half_across) &&
         inside_even_odd(top, centre - half_along + half_across) &&
         inside_even_odd(top, centre - half_along - half_across)))
      return kSoleSamples;
  }
  int held = 0, missed = 0;
  for (int i = 0; i < kSoleRows && missed <= may_miss; ++i) {
    for (int j = 0; j < kSoleColumns && missed <= may_miss; ++j) {
      const Vec2 offset = ((i + 0.5) / kSoleRows - 0.5) * sole.length * along +
                          ((j + 0.5) / kSoleColumns - 0.5) * sole.width * across;
      const Vec2 p = centre + offset;
      // The sole's plane over p.
      const double plane =
          sole.centre.z - (sole.normal.x * offset.x + sole.normal.y * offset.y) / sole.normal.z;
      // The grid stretched to the sole's outline, its heel rounded (the heel
      // row half as wide; a shoe's toe is about as wide as its ball): no
      // ground above the sole there, below the instep, where the foot would
      // be in it (a riser).
      const bool heel_row = i == 0;
      const Vec2 edge_offset =
          (static_cast<double>(i) / (kSoleRows - 1) - 0.5) * (sole.length + 2 * kToeRoom) * along +
          ((heel_row ? 0.5 : 1.0) * (static_cast<double>(j) / (kSoleColumns - 1) - 0.5) *
           sole.width) * across;
      const Vec2 edge = centre + edge_offset;
      const double edge_plane = sole.centre.z - (sole.normal.x * edge_offset.x +
                                                 sole.normal.y * edge_offset.y) / sole.normal.z;
      bool supported = false;
      for (const Face* face : near) {
        if (covers(*face, edge, edge_plane + tolerance, edge_plane + kInstep) &&
            in_box(*face, edge) && contains(*face, edge))
          return 0;
        if (in_box(*face, p) && contains(*face, p))
          supported = supported || (face->walkable && face->normal.z >= min_normal_z &&
                                    std::fabs(height_of(*face, p) - plane) <= tolerance);
      }
      held += supported ? 1 : 0;
      missed += supported ? 0 : 1;
    }
  }
  return held;
}

namespace {

/// An obstacle's outline points in plan and their middle: where the ground
/// under it is looked for.
std::vector<Vec2> outline_and_middle(const Obstacle& obstacle) {
  std::vector<Vec2> outline = obstacle.polygon;
  for (const Vec3 v : obstacle.mesh.vertices) outline.push_back(footfall::ground(v));
  if (outline.empty()) return outline;
  Vec2 middle{0, 0};
  const double share = 1.0 / static_cast<double>(outline.size());
  for (const Vec2 p : outline) middle = middle + share * p;
  outline.push_back(middle);
  return outline;
}

double top_of(const Obstacle& obstacle) {
  if (!obstacle.is_mesh()) return obstacle.height;
  double top = -std::numeric_limits<double>::infinity();
  for (const Vec3 v : obstacle.mesh.vertices) top = std::max(top, v.z);
  return top;
}

}  // namespace

std::vector<double> cut_heights(const Ground& ground, const std::vector<Obstacle>& obstacles,
                                double headroom) {
  std::vector<double> cuts;
  cuts.reserve(obstacles.size());
  for (const Obstacle& obstacle : obstacles) {
    double under = -std::numeric_limits<double>::infinity();
    if (!ground.empty())
      for (const Vec2 p : outline_and_middle(obstacle))
        for (const GroundPoint& level : ground.standable_at(p, headroom))
          under = std::max(under, level.z);
    cuts.push_back((std::isfinite(under) ? under : 0.0) + headroom);
  }
  return cuts;
}

std::vector<double> cut_heights(const GroundLayers& layers, const std::vector<Obstacle>& obstacles,
                                int layer) {
  const double headroom = layers.headroom();
  std::vector<double> cuts;
  cuts.reserve(obstacles.size());
  for (const Obstacle& obstacle : obstacles) {
    double under = -std::numeric_limits<double>::infinity();
    for (const Vec2 p : outline_and_middle(obstacle))
      if (const std::optional<GroundPoint> level = layers.level_on(p, layer))
        under = std::max(under, level->z);
    // Off the layer's ground, or wholly under it (a pier under a deck): nothing to cut.
    const bool apart = !std::isfinite(under) || top_of(obstacle) <= under + Ground::kSameLevel;
    cuts.push_back(apart ? -std::numeric_limits<double>::infinity() : under + headroom);
  }
  return cuts;
}

}  // namespace footfall
