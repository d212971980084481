// Footfall — the walkable ground of a scene (a scenario's "ground"): prisms
// whose tops are floors, treads, platforms and decks, and meshes whose
// upward-facing triangles are ramps, hills and scanned terrain. Indexed for
// the questions a footstep planner asks of the ground under a point: which
// levels lie there, which one is near a height, how much of a sole it holds.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "footfall/model/geometry3.hpp"
#include "footfall/model/obstacles.hpp"

namespace footfall {

/// A ground surface: a prism (polygon, `height` of the top walked on, `base`
/// of its underside; height may be 0 or negative) or a mesh. The same shapes
/// as obstacles, read from the same fields.
using GroundSurface = Obstacle;

/// A ground surface as a scenario gives it: a prism from `base` (default
/// min(0, height)) to `height`.
GroundSurface ground_prism(std::vector<Vec2> polygon, double height);

/// The ground at a point: the height of one walkable face there, its upward
/// unit normal and the surface it belongs to.
struct GroundPoint {
  double z = 0;   ///< [m]
  Vec3 normal;    ///< Unit, normal.z > 0.
  int surface = -1;  ///< Index into Ground::surfaces().
  int face = -1;     ///< The walkable face, as Ground numbers them (GroundLayers::layer_of).
};

/// A sole on the ground: a rectangle `length` along `heading` by `width`,
/// centred on `centre`, lying in the plane through `centre` with `normal`.
struct Sole {
  Vec3 centre;         ///< [m]
  Vec3 normal{0, 0, 1};  ///< Unit, normal.z > 0.
  double heading = 0;  ///< [rad]
  double length = 0;   ///< Heel to toe. [m]
  double width = 0;    ///< [m]
};

/// A wall of the ground in plan: an edge of standable ground with no
/// standable level within a step across it.
struct GroundWall {
  Vec2 a, b;  ///< [m]
};

/// Where two layers of the ground meet within a step: a run of an edge with
/// one layer's ground on its side and the other's across it.
struct GroundPortal {
  Vec2 a, b;             ///< [m]
  int from = 0, to = 0;  ///< The layer on the edge's side, and the one across.
  Vec2 across;           ///< Unit, in plan from `from`'s side to `to`'s.
};

class Ground;

/// Standable ground split into layers, each with at most one level over any
/// point: one layer where no levels lie above one another; a street and a
/// bridge's deck over it in two, joined by portals where the deck meets its
/// stairs or ramps. Each layer has its own walls, which close round its ground
/// (and across its portals). Refers to the ground it was made from.
class GroundLayers {
 public:
  /// More layers are refused: each one is a navigation mesh of the whole scene.
  static constexpr int kMaxLayers = 64;

  int count() const { return static_cast<int>(walls_.size()); }
  /// The layer of a standable level (a point from standable_at or level_on).
  int layer_of(const GroundPoint& point) const {
    return face_layer_.empty() || point.face < 0 ? 0 : face_layer_[point.face];
  }
  /// The standable level of `layer` over `p`, if any.
  std::optional<GroundPoint> level_on(Vec2 p, int layer) const;
  /// The walls of a layer: edges of its ground no one on it steps across
  /// (Ground::walls, each layer on its own).
  const std::vector<GroundWall>& walls(int layer) const { return walls_.at(layer); }
  const std::vector<GroundPortal>& portals() const { return portals_; }
  /// The headroom the layers were found for. [m]
  double headroom() const { return headroom_; }
  /// The ground they split.
  const Ground& ground() const { return *ground_; }

 private:
  friend class Ground;
  const Ground* ground_ = nullptr;
  double headroom_ = 0;
  std::vector<int> face_layer_;  ///< Per face; empty with one layer.
  std::vector<std::vector<GroundWall>> walls_;
  std::vector<GroundPortal> portals_;
};

/// The walkable ground, indexed. Immutable after construction, so it can be
/// shared between threads.
class Ground {
 public:
  /// At most this many triangles over all meshes: a bound on the index's
  /// memory (some 100 bytes a triangle) and the time to build it.
  static constexpr std::size_t kMaxTriangles = 2'000'000;
  /// Within this height of each other, faces over a point are one level
  /// (the triangles either side of a shared edge). [m]
  static constexpr double kSameLevel = 1e-3;

  /// Checks and indexes `surfaces`; throws std::invalid_argument naming the
  /// field ("ground[3].polygon[1]: ...", "ground[0].mesh.triangles[7][2]:
  /// ...", "ground: ... triangles, at most ..."). No surfaces: no ground.
  explicit Ground(std::vector<GroundSurface> surfaces = {});

  /// True if the scene has no ground given (the plane z = 0 is its floor).
  bool empty() const { return surfaces_.empty(); }
  const std::vector<GroundSurface>& surfaces() const { return surfaces_; }
  /// Walkable faces: prism tops and upward-facing triangles.
  std::size_t walkable_faces() const { return walkable_faces_; }

  /// Every level of walkable ground over `p`, lowest first.
  std::vector<GroundPoint> levels_at(Vec2 p) const;
  /// The levels over `p` a body `headroom` tall can stand on: those with no
  /// ground's face or prism within (z, z + headroom] over `p` (a floor under
  /// a platform's prism, or under a deck too low to walk beneath, is
  /// covered), lowest first.
  std::vector<GroundPoint> standable_at(Vec2 p, double headroom) const;
  /// The lowest of standable_at(p, headroom), if any: on ground of one level
  /// at every point, the ground under a foot.
  std::optional<GroundPoint> standing_on(Vec2 p, double headroom) const;
  /// Of standable_at(p, headroom), the nearest the height `z`, if any: the
  /// level a foot is on, given the height of the ground it was on (levels
  /// over one point lie a body's height apart, steps far less).
  std::optional<GroundPoint> standable_near(Vec2 p, double z, double headroom) const;
  /// The edges of standable ground (standable_at) a body `headroom` tall
  /// cannot step across: where, 2 cm across, no standable level lies within
  /// `max_step` of the edge's height (a flight's sides, a platform's edge,
  /// the rim of all ground, the border of a face facing down), sampled every
  /// 5 cm; ground steeper than a normal's `min_normal_z` (the cosine of the
  /// steepest walkable slope) is no standable level, so a slope too steep is
  /// walled round. They close round every piece of ground a walker can
  /// reach. Edges a mesh's two walkable triangles share are not walls, but
  /// where one of them is too steep.
  std::vector<GroundWall> walls(double max_step, double headroom, double min_normal_z) const;
  /// The ground's layers for a body `headroom` tall stepping at most
  /// `max_step` up or down, on slopes whose normal has at least
  /// `min_normal_z` (walls()): faces standable over one point (sampled every
  /// 5 cm along each walkable face's edges, 2 cm inside it: where two faces
  /// overlap, one's edge runs inside the other) lie in different layers, each face in the
  /// first layer it fits. Throws std::invalid_argument ("ground: ...") past
  /// GroundLayers::kMaxLayers.
  GroundLayers layers(double max_step, double headroom, double min_normal_z) const;
  /// The level over `p` nearest the height `z`, if one lies within `reach`.
  std::optional<GroundPoint> level_near(Vec2 p, double z, double reach) const;
  /// The share of `sole` (sampled on a 7 x 4 grid) over a walkable face
  /// within `tolerance` of the sole's plane, on a slope whose normal has at
  /// least `min_normal_z` (the cosine of the steepest walkable slope); 0
  /// where any point of the sole's outline (its heel rounded, and 1 cm of
  /// room before the toe and behind the heel) has ground over the
  /// sole's plane, above `tolerance` and up to the instep (0.1 m): a toe in
  /// a riser is no foothold. [0, 1]
  double support(const Sole& sole, double tolerance, double min_normal_z) const;
  /// True if support() is at least `share`; stops sampling once it cannot be.
  bool holds(const Sole& sole, double tolerance, double min_normal_z, double share) const;

 private:
  /// A prism's top, or a mesh triangle that is not on edge: walkable if it
  /// faces up, else only solid (it may cover a level below it).
  struct Face {
    int surface = -1;
    int triangle = -1;  ///< Into the mesh's triangles; -1 for a prism's top.
    Vec3 normal;        ///< Unit.
    double d = 0;       ///< The face's plane: dot(normal, x) = d.
    bool walkable = false;
    Box box{};          ///< Its extent in plan: most points outside it are told by it alone.
  };
  /// Each face is kept in the cells of the first level on which its box
  /// spans at most 16; the levels' cells grow by four from 0.5 m.
  struct IndexLevel {
    double cell = 0;  ///< [m]
    std::unordered_map<std::uint64_t, std::vector<int>> cells;
  };

  void add_face(Face face, Vec2 low, Vec2 high);
  /// Calls visit(a, b, za, zb, outward) for each edge of each walkable face
  /// but those a mesh's two walkable triangles (faces f and g) share where
  /// keep_shared(f, g) is false: its ends in plan and their heights, and the
  /// unit normal pointing out of the face.
  template <class Visit, class KeepShared>
  void visit_walkable_edges(Visit&& visit, KeepShared&& keep_shared) const;
  /// Calls visit(p) at points every 5 cm along each walkable face's edges
  /// (but those a mesh's walkable triangles share), 2 cm inside the face.
  template <class Visit>
  void visit_inner_edge_samples(Visit&& visit) const;
  /// The samples of support()'s grid held, counting until `may_miss` are
  /// not (then fewer than all that are held may be counted).
  int soles_samples_held(const Sole& sole, double tolerance, double min_normal_z,
                         int may_miss) const;
  /// The levels of the walkable faces among `here`, which hold `p`.
  std::vector<GroundPoint> levels_of(const std::vector<const Face*>& here, Vec2 p) const;
  static bool in_box(const Face& face, Vec2 p) {
    return p.x >= face.box.min.x && p.x <= face.box.max.x && p.y >= face.box.min.y &&
           p.y <= face.box.max.y;
  }
  bool contains(const Face& face, Vec2 p) const;
  double height_of(const Face& face, Vec2 p) const;
  /// True if `face` holds solid ground within (z, top] over `p`.
  bool covers(const Face& face, Vec2 p, double z, double top) const;
  template <class Visit>
  void visit_faces_at(Vec2 p, Visit&& visit) const;

  std::vector<GroundSurface> surfaces_;
  std::vector<bool> convex_;  ///< Per surface: a prism whose top is convex.
  std::vector<Face> faces_;
  std::size_t walkable_faces_ = 0;
  std::vector<IndexLevel> index_;
};

/// Per obstacle, the height below which it blocks footsteps: `headroom`
/// above the highest standable ground under it (at its outline's points and
/// their middle), or above 0 where there is none or no ground at all.
std::vector<double> cut_heights(const Ground& ground, const std::vector<Obstacle>& obstacles,
                                double headroom);
/// The same for the ground of one of several layers: the layer's ground
/// under each obstacle; -infinity (it blocks nothing on the layer) where it
/// stands off that ground or wholly under it (a bridge's pier under its deck).
std::vector<double> cut_heights(const GroundLayers& layers, const std::vector<Obstacle>& obstacles,
                                int layer);

}  // namespace footfall
