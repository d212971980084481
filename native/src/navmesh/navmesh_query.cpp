// Footfall — path queries: a search over (triangle, entry edge) states that
// skips traversals too narrow for the disc, the funnel through each channel
// it offers, and an exact clearance check of every funnel path.
//
// Channels come out in order of a lower bound on the length of any path
// through them (the shortest start-portal-goal detour over each portal, kept
// r from its ends), so the first clear funnel path whose length is at most
// the next channel's bound is the shortest of all channels searched. The
// narrowness tests (portal length and corner width, both at least 2r, and
// some point of the portal r clear of the two faces beside it) are
// necessary conditions: they never drop a channel a disc could pass. They are
// not sufficient everywhere (an obstacle further off can still pinch a
// channel they accept), which is why every funnel path is measured against
// the obstacles; a channel that fails is skipped and the search goes on.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <unordered_set>

#include "navmesh/channel_funnel.hpp"
#include "navmesh/face_numbers.hpp"
#include "navmesh/navmesh_impl.hpp"
#include "navmesh/obstacle_distance.hpp"
#include "navmesh/open_list.hpp"
#include "util/scratch_vector.hpp"

namespace footfall {
namespace {

constexpr int kNoEdge = 3;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
/// How far back a new triangle is looked for in its own channel (a byte
/// each in Node::recent).
constexpr int kLoopCheck = 8;
/// The search offers channels in order of their lower bound with the part
/// still ahead weighted by this factor, and stops once no channel left can
/// be shorter than the best path by more than kLengthTolerance: the answer
/// is within (1 + kLengthTolerance) * kAheadWeight (0.8 %) of the shortest
/// path through any channel it could offer. The weight keeps long queries
/// over open ground from widening the search to every detour of similar
/// length.
constexpr double kAheadWeight = 1.005;
constexpr double kLengthTolerance = 0.003;
/// A disc's path through a channel that comes out longer than the channel's
/// relaxed length by more than this share shows that the relaxation, which
/// prices the turns at gate ends as chords, misjudged it: a channel the
/// search pruned for a longer relaxed length may then be shorter for the
/// disc, so the search runs again with rivals. Most queries never need it;
/// 1 % is the oracle tests' allowance.
constexpr double kRelaxedTrust = 0.01;
/// The flood that tells a goal sealed off in a pocket goes on every
/// kPocketCheckEvery expansions of the search, up to kPocketFloodStart states
/// and one more for every kPocketFloodShare nodes expanded, and gives up
/// after kPocketFlood states. Most pockets are small; a larger share would
/// slow the queries that have a path to find.
constexpr int kPocketCheckEvery = 16;
constexpr int kPocketFloodStart = 16;
constexpr int kPocketFloodShare = 8;
constexpr int kPocketFlood = 2048;
/// Dominated nodes kept per edge when a search is run again because a
/// channel it offered failed for the disc.
constexpr int kRivalsOnRetry = 4;
/// Share of a gate within which a clipped interval's end is taken to be the gate's.
constexpr double kEndSnap = 1e-9;
/// Rounding allowance when comparing a measured clearance with the radius. [m]
constexpr double kClearanceSlack = 1e-9;

/// The part of a portal a disc's centre can cross: the portal kept `radius`
/// from both ends (every mesh vertex is on an obstacle).
struct Gate {
  Vec2 left, right;  ///< As seen walking through.
};

Gate gate_of(Vec2 left, Vec2 right, double radius) {
  const Vec2 d = right - left;
  const double len = length(d);
  const double keep = std::min(radius, 0.5 * len) / len;
  return {left + keep * d, right - keep * d};
}

/// The shortest |from - q| + |q - to| over q on segment [lo, hi].
double via_segment(Vec2 from, Vec2 to, Vec2 lo, Vec2 hi) {
  const Vec2 d = hi - lo;
  const double len = length(d);
  if (len == 0.0) return distance(from, lo) + distance(lo, to);
  const Vec2 u = d * (1.0 / len);
  // Mirror `to` to the far side of the segment's line; the straight line from
  // `from` then meets the line where the detour is shortest, and the detour
  // is convex along the line, so clamping to the segment gives its minimum.
  const double sf = cross(u, from - lo), st = cross(u, to - lo);
  const Vec2 mirrored = (sf > 0) == (st > 0) && sf != 0 ? to - 2 * st * perp(u) : to;
  const double sm = cross(u, mirrored - lo);
  const double along =
      sf == sm ? dot(from - lo, u) : dot(from + (sf / (sf - sm)) * (mirrored - from) - lo, u);
  const Vec2 q = lo + std::clamp(along, 0.0, len) * u;
  return distance(from, q) + distance(q, to);
}

/// One search node, after Polyanya (Cui, Harabor and Grastien, IJCAI 2017):
/// the paths that come into `face` through `interval`, a part of a gate seen
/// whole from `root`, the point where the shortest of them last turned.
/// Lengths are relaxed: gates instead of the disc, so they never exceed the
/// length of a disc's path through the same channel.
/// Its lower bound f is kept in the open list only: a smaller node is fewer
/// cache lines for the dominance test, which reads interval, root and g of
/// every node kept on an edge.
struct Node {
  Face face;
  Gate interval;
  Vec2 root;
  double g;  ///< Relaxed length from the start to `root`.
  /// The low byte of the slot of its face, then of its parent's, and so on
  /// back kLoopCheck faces: most new faces miss them all, and need no walk
  /// back to rule out a loop.
  std::uint64_t recent;
  int slot;       ///< Where the search keeps what it knows of `face`.
  int entry;      ///< Edge of `face` the interval lies on (kNoEdge: the start).
  int parent;     ///< -1 for the start.
  int same_edge;  ///< The node kept before it that came in through the same edge (or -1).
  bool left_end, right_end;  ///< The interval ends where its gate does: a path may turn there.
};

/// Triangles from start to goal and the portals between them: portal k
/// joins faces[k] and faces[k + 1].
struct Channel {
  std::vector<Face> faces;
  std::vector<Portal> portals;
};

/// Where `segment` lies on the side of the line from `origin` along `dir`
/// that `side` gives (+1 left, -1 right), as parameters [t0, t1] along it;
/// false if nowhere (touching at one point counts when `touch` is true).
bool clip_to_side(const Gate& segment, double& t0, double& t1, Vec2 origin, Vec2 dir, double side,
                  bool touch) {
  const Vec2 d = segment.right - segment.left;
  const double s0 = side * cross(dir, segment.left + t0 * d - origin);
  const double s1 = side * cross(dir, segment.left + t1 * d - origin);
  if (s0 < 0 && s1 < 0) return false;
  if (!touch && s0 <= 0 && s1 <= 0) return false;
  const double cut = t0 + (t1 - t0) * s0 / (s0 - s1);
  if (s0 < 0)
    t0 = cut;
  else if (s1 < 0)
    t1 = cut;
  return true;
}

/// Offers the channels from the start's triangle to the goal's in order of
/// a lower bound on any path through them (weighted as kAheadWeight says).
/// A node is dropped when another reaches the same edge with a relaxed
/// length at least as short everywhere on it, or its turning point sooner:
/// exact for the relaxed lengths, but a channel the relaxation favours can
/// still fail for the disc. So a search that saw one fail is run again with
/// `rivals`: that many dominated nodes per edge are kept, and turning points
/// are not pruned (with none pruned at all, the channels would multiply
/// without bound).
class ChannelSearch {
 public:
  ChannelSearch(const NavMeshState& mesh, const PathQuery& q, Face start, Face goal, int rivals)
      : mesh_(mesh), q_(q), goal_(goal), rivals_(rivals) {
    searched_.reserve(256);
    nodes_.reserve(256);
    const double straight = distance(q_.from, q_.to);
    const Gate at_start{q_.from, q_.from};
    const int start_slot = slot(start);
    nodes_.push_back({start, at_start, q_.from, 0.0, static_cast<std::uint8_t>(start_slot),
                      start_slot, kNoEdge, -1, -1, false, false});
    open_.push({straight, 0});
    flood_.push_back({goal, kNoEdge});
  }

  /// The next channel to the goal, in order of the lower bound on the length
  /// of a path through it (its relaxed length, `bound_out`); false when none
  /// is left whose bound is below `limit`. A node's successors have bounds of
  /// at least its f / kAheadWeight (the unweighted bound never falls along a
  /// channel), so once every open node is at kAheadWeight * limit or more, no
  /// channel left can qualify: a query whose answer is found stops there
  /// instead of searching on for a goal's face that may have no other way in.
  bool next(Channel& channel, double limit, double& bound_out) {
    while (!open_.empty() && open_.top().first < kAheadWeight * limit) {
      const auto [bound, index] = open_.top();
      open_.pop();
      // A long search may be walking all the ground around a goal no disc
      // can reach; a flood from the goal tells that at a fraction of the cost.
      if (++expanded_ % kPocketCheckEvery == 0 && goal_sealed_off()) return false;
      if (nodes_[index].face == goal_ && nodes_[index].entry != kNoEdge) {
        if (bound >= limit) return false;
        bound_out = bound;
        unwind(index, channel);
        return true;
      }
      expand(index);
    }
    return false;
  }

 private:
  /// What the search knows of one face: its handle, its corners' widths (NaN
  /// until measured), whether a disc can cross each edge at all, the face
  /// beyond each edge (its slot, -1 until looked up, and the edge's index
  /// there: a face is expanded several times, the mesh read once), and, per
  /// entry edge, the last node kept that came in through it, how many dominated
  /// ones were kept anyway, and the shortest relaxed length to each end of
  /// its gate for a path that turns there; and which states (face, entry
  /// edge) the pocket check's flood has seen, one bit per entry.
  enum Tested : char { kUntested, kPasses, kFails };
  struct FaceSearch {
    Face face;
    std::array<double, 3> corner_width{kNaN, kNaN, kNaN};
    std::array<Tested, 3> crossing{kUntested, kUntested, kUntested};
    std::array<std::int8_t, 3> back{-1, -1, -1};
    std::array<int, 3> beyond{-1, -1, -1};
    std::array<int, 3> last_in{-1, -1, -1};
    std::array<int, 3> rivals{0, 0, 0};
    std::array<std::array<double, 2>, 3> turn_g{{{kInf, kInf}, {kInf, kInf}, {kInf, kInf}}};
    unsigned char flooded = 0;
  };
  /// The slot of `f` in `searched_`, made on its first visit. Slots are
  /// indices, not references: a new face can move every other.
  int slot(Face f) {
    const auto [number, fresh] = numbers_.insert(f);
    if (fresh) searched_.emplace_back().face = f;
    return number;
  }
  /// The slot of the face beyond edge `exit` of the face in slot `here`, and
  /// the index of that edge there.
  std::pair<int, int> beyond(int here, int exit) {
    if (searched_[here].beyond[exit] < 0) {
      const Face f = searched_[here].face, next = f->neighbor(exit);
      const int entry = next->index(f);
      // A face is expanded soon after it is met: ask now for the records its
      // expansion reads (its far corner and the faces beyond its exits), so
      // that their cache misses overlap with other work.
      __builtin_prefetch(&*next->vertex(entry));
      __builtin_prefetch(&*next->neighbor(Cdt::cw(entry)));
      __builtin_prefetch(&*next->neighbor(Cdt::ccw(entry)));
      const int there = slot(next);  // may move searched_
      searched_[here].beyond[exit] = there;
      searched_[here].back[exit] = static_cast<std::int8_t>(entry);
    }
    return {searched_[here].beyond[exit], searched_[here].back[exit]};
  }
  enum Turn { kLeft = 0, kRight = 1 };

  void expand(int index) {
    const Node node = nodes_[index];
    const Face f = node.face;
    const int here = node.slot;
    if (node.entry == kNoEdge) {  // the start's triangle: every gate is seen whole
      for (int exit = 0; exit < 3; ++exit)
        if (passable(node, searched_[here], exit) && reaches_goal(f, exit))
          push(index, exit, exit_gate(f, exit), true, true, node.root, node.g);
      return;
    }
    // The tests of both exits read the corners of the faces beyond them.
    for (const int exit : {Cdt::cw(node.entry), Cdt::ccw(node.entry)})
      for (int corner = 0; corner < 3; ++corner)
        __builtin_prefetch(&*f->neighbor(exit)->vertex(corner));
    const Vec2 at_left = node.interval.left, at_right = node.interval.right;
    const Vec2 to_left = at_left - node.root, to_right = at_right - node.root;
    // A root on the interval's line (the start on an edge, or rounding)
    // sees everything ahead; a straight line is never too long a bound.
    const bool sees_all =
        std::abs(cross(at_right - at_left, node.root - at_left)) <= 1e-12 * dot(to_left, to_left) ||
        cross(to_left, to_right) >= 0;
    for (const int exit : {Cdt::cw(node.entry), Cdt::ccw(node.entry)}) {
      if (!passable(node, searched_[here], exit) || !reaches_goal(f, exit)) continue;
      const Gate gate = exit_gate(f, exit);
      if (sees_all) {
        push(index, exit, gate, true, true, node.root, node.g);
        continue;
      }
      // Seen from the root: right of the ray through the interval's left end
      // and left of the ray through its right end.
      double t0 = 0.0, t1 = 1.0;
      if (clip_to_side(gate, t0, t1, node.root, to_left, -1, true) &&
          clip_to_side(gate, t0, t1, node.root, to_right, +1, true))
        push_part(index, exit, gate, t0, t1, node.root, node.g);
      // Hidden from the root, beyond an end of the interval where its gate
      // ends: the path turns round that end (the first to get there does).
      double h0 = 0.0, h1 = 1.0;
      if (node.left_end && clip_to_side(gate, h0, h1, node.root, to_left, +1, false)) {
        const double via_left = node.g + length(to_left);
        if (first_to_turn(searched_[here], node.entry, kLeft, via_left))
          push_part(index, exit, gate, h0, h1, at_left, via_left);
      }
      h0 = 0.0, h1 = 1.0;
      if (node.right_end && clip_to_side(gate, h0, h1, node.root, to_right, -1, false)) {
        const double via_right = node.g + length(to_right);
        if (first_to_turn(searched_[here], node.entry, kRight, via_right))
          push_part(index, exit, gate, h0, h1, at_right, via_right);
      }
    }
  }

  /// The gate of `f`'s edge `exit`, as seen walking out through it.
  Gate exit_gate(Face f, int exit) const {
    return gate_of(to_vec(f->vertex(Cdt::cw(exit))->point()),
                   to_vec(f->vertex(Cdt::ccw(exit))->point()), q_.radius);
  }

  void push_part(int index, int exit, const Gate& gate, double t0, double t1, Vec2 root, double g) {
    // A part clipped at a gate's end up to rounding ends there: a path may
    // turn at that end, and admit() drops a path that turns there separately
    // as no shorter (on a grid, roots and gate ends are often collinear).
    if (t0 <= kEndSnap) t0 = 0.0;
    if (t1 >= 1.0 - kEndSnap) t1 = 1.0;
    const Vec2 d = gate.right - gate.left;
    push(index, exit, {gate.left + t0 * d, gate.left + t1 * d}, t0 == 0.0, t1 == 1.0, root, g);
  }

  void push(int index, int exit, const Gate& interval, bool left_end, bool right_end, Vec2 root,
            double g) {
    const auto [slot_there, entry] = beyond(nodes_[index].slot, exit);
    FaceSearch& there = searched_[slot_there];
    const Face next = there.face;
    // The goal's face may be the start's, when the straight line between
    // them is blocked: a channel may come back to it round a corner.
    if (next != goal_ && circles_back(index, slot_there)) return;
    if (!admit(there, entry, interval, root, g)) return;
    const double f = g + kAheadWeight * via_segment(root, q_.to, interval.left, interval.right);
    const std::uint64_t recent = nodes_[index].recent << 8 | static_cast<std::uint8_t>(slot_there);
    nodes_.push_back({next, interval, root, g, recent, slot_there, entry, index,
                      there.last_in[entry], left_end, right_end});
    there.last_in[entry] = static_cast<int>(nodes_.size() - 1);
    open_.push({f, static_cast<int>(nodes_.size() - 1)});
  }

  /// False if a node kept before that came into `face` through `entry`
  /// covers `interval` and is no longer anywhere on it than g + |root - p|
  /// (by the triangle inequality, when its length to `root` is no more than
  /// g), unless rivals are left.
  bool admit(FaceSearch& face, int entry, const Gate& interval, Vec2 root, double g) const {
    constexpr double kSlack = 1e-9;
    for (int i = face.last_in[entry]; i >= 0; i = nodes_[i].same_edge) {
      const Node& a = nodes_[i];
      const Vec2 d = a.interval.right - a.interval.left;
      const double dd = dot(d, d);
      const double t0 = dd > 0 ? dot(interval.left - a.interval.left, d) / dd : 0.0;
      const double t1 = dd > 0 ? dot(interval.right - a.interval.left, d) / dd : 0.0;
      if (t0 >= -kSlack && t1 <= 1 + kSlack && a.g + distance(a.root, root) <= g + kSlack)
        return face.rivals[entry]++ < rivals_;
    }
    return true;
  }

  /// True if no path seen so far turned at the `side` end of `face`'s gate
  /// `entry` sooner than g (and records g); with rivals, every path may.
  bool first_to_turn(FaceSearch& face, int entry, Turn side, double g) const {
    double& best = face.turn_g[entry][side];
    if (g > best && rivals_ == 0) return false;
    best = std::min(best, g);
    return true;
  }

  /// True if the goal's triangle lies in a pocket the disc cannot leave: a
  /// flood from it over the traversals the search accepts ends without
  /// meeting the start's triangle. The flood goes on where it stopped, as far
  /// as the search's progress allows, so a goal in a small pocket is told
  /// early, and a search with a path to find pays little for it.
  bool goal_sealed_off() {
    const auto budget = static_cast<std::size_t>(
        std::min(kPocketFloodStart + expanded_ / kPocketFloodShare, kPocketFlood));
    while (!flood_.empty()) {
      if (flooded_ >= budget) return false;
      const auto [f, entry] = flood_.back();
      flood_.pop_back();
      if (f == nodes_.front().face) {
        flood_.clear();
        flood_met_start_ = true;
        break;
      }
      Node at{};
      at.face = f;
      at.entry = entry;
      at.root = q_.to;  // read only where the flood starts, at the goal
      const int here = slot(f);
      for (int exit = 0; exit < 3; ++exit) {
        if (exit == entry || !passable(at, searched_[here], exit)) continue;
        const auto [there, entry_there] = beyond(here, exit);
        const Face next = searched_[there].face;
        unsigned char& seen = searched_[there].flooded;
        if (seen & (1u << entry_there)) continue;
        seen = static_cast<unsigned char>(seen | (1u << entry_there));
        ++flooded_;
        flood_.push_back({next, entry_there});
      }
    }
    return !flood_met_start_;
  }

  /// True if the channel ending at node `index` passed through the face in
  /// `face_slot` in its last kLoopCheck steps: a channel that circles back is
  /// never the shortest.
  bool circles_back(int index, int face_slot) const {
    static_assert(kLoopCheck == sizeof(Node::recent));
    constexpr std::uint64_t kOnes = 0x0101010101010101ull;
    const std::uint64_t x = nodes_[index].recent ^ (kOnes * static_cast<std::uint8_t>(face_slot));
    if (((x - kOnes) & ~x & (kOnes << 7)) == 0) return false;  // no byte of x is zero
    for (int i = index, k = 0; i >= 0 && k < kLoopCheck; i = nodes_[i].parent, ++k)
      if (nodes_[i].slot == face_slot) return true;
    return false;
  }

  bool passable(const Node& node, FaceSearch& here, int exit) {
    const Face f = node.face;
    // Tested before the corner: the edge's test is cheaper than a corner's
    // walk, and with a large radius many edges fail it.
    Tested& crossing = here.crossing[exit];
    if (crossing == kUntested) crossing = crossable(f, exit) ? kPasses : kFails;
    if (crossing == kFails) return false;
    if (node.entry == kNoEdge) return reaches(f, exit, node.root);
    // Each corner's width is measured once per query, however often its
    // face is expanded (the walk behind it is the costly part).
    const double need = 2 * q_.radius;
    double& width = here.corner_width[3 - node.entry - exit];
    if (std::isnan(width)) width = corner_width(mesh_, f, 3 - node.entry - exit, need);
    return width >= need;
  }

  /// False if no disc can cross edge `exit` of `f`, whatever way it comes:
  /// the edge is an obstacle's or leads out of the walkable space, is
  /// shorter than 2r, or no point of it is r clear of the faces beside it.
  bool crossable(Face f, int exit) const {
    if (f->is_constrained(exit) || !mesh_.walkable(f->neighbor(exit))) return false;
    const Vec2 a = to_vec(f->vertex(Cdt::ccw(exit))->point());
    const Vec2 b = to_vec(f->vertex(Cdt::cw(exit))->point());
    if (distance(a, b) < 2 * q_.radius) return false;
    // The corner tests look across one edge only; an obstacle of the face
    // beyond the portal can still leave no point of it clear (a disturbance).
    // Points clear by r less the measuring slack count as crossings.
    return !portal_covered(f, exit, q_.radius - 2 * kClearanceSlack);
  }

  /// False if a disc at `p` in face `f` cannot reach edge `exit` of `f`
  /// without leaving `f`: the corner test for a path that starts or ends
  /// inside a face, looking across the opposite edge only between the
  /// corner's edge and p.
  bool reaches(Face f, int exit, Vec2 p) const {
    const double need = 2 * q_.radius;
    const Vec2 a = to_vec(f->vertex(Cdt::ccw(exit))->point());
    const Vec2 b = to_vec(f->vertex(Cdt::cw(exit))->point());
    return wedge_width(mesh_, f, Cdt::ccw(exit), b, p, need) >= need &&
           wedge_width(mesh_, f, Cdt::cw(exit), p, a, need) >= need;
  }

  /// False if the edge `exit` of `f` leads into the goal's face, from where
  /// the disc cannot reach the goal.
  bool reaches_goal(Face f, int exit) {
    const Face next = f->neighbor(exit);
    if (next != goal_) return true;
    const int entry = next->index(f);
    if (goal_entry_[entry] == kUntested)
      goal_entry_[entry] = reaches(next, entry, q_.to) ? kPasses : kFails;
    return goal_entry_[entry] == kPasses;
  }

  void unwind(int index, Channel& channel) const {
    channel.portals.clear();
    channel.faces = {nodes_[index].face};
    for (int i = index; nodes_[i].parent >= 0; i = nodes_[i].parent) {
      // Walking out of the parent through this edge: its ends as seen from the parent.
      const Face from = nodes_[nodes_[i].parent].face;
      const int edge = from->index(nodes_[i].face);
      channel.portals.push_back({to_vec(from->vertex(Cdt::cw(edge))->point()),
                                 to_vec(from->vertex(Cdt::ccw(edge))->point())});
      channel.faces.push_back(from);
    }
    std::reverse(channel.portals.begin(), channel.portals.end());
    std::reverse(channel.faces.begin(), channel.faces.end());
  }

  const NavMeshState& mesh_;
  const PathQuery& q_;
  Face goal_;
  int rivals_;
  std::array<Tested, 3> goal_entry_{kUntested, kUntested, kUntested};  ///< Per goal face edge.
  int expanded_ = 0;
  /// The pocket check's flood: the states still to visit, and how many it has seen.
  std::vector<std::pair<Face, int>> flood_;
  std::size_t flooded_ = 0;
  bool flood_met_start_ = false;
  ScratchVector<Node> node_storage_;
  std::vector<Node>& nodes_ = *node_storage_;
  /// (f, node), f a lower bound on any path through the node to the goal:
  /// lowest first.
  OpenList open_;
  FaceNumbers numbers_;
  ScratchVector<FaceSearch> face_storage_;
  std::vector<FaceSearch>& searched_ = *face_storage_;
};

/// Where a polyline comes nearest to the obstacles.
struct Pinch {
  double clearance = std::numeric_limits<double>::infinity();
  NearestObstacle obstacle;   ///< The obstacle point there, and its edge.
  Vec2 path_point;            ///< The polyline's point nearest to it.
  Vec2 heading;               ///< The polyline's direction there.
  double along = 0.0;         ///< Length of the polyline up to `path_point`.
  bool in_free_space = true;  ///< False if a point of the polyline is not walkable.
};

/// Where `points` come nearest to the obstacles, looking only within `reach`
/// of them (clearance infinite if nothing is that near): the walk then stays
/// in the faces along the path.
Pinch find_pinch_within(const NavMeshState& mesh, const std::vector<Vec2>& points, double reach) {
  Pinch pinch;
  pinch.clearance = reach;
  Face hint = mesh.hints.near(to_point(points.front()));
  double along = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Vec2 a = points[k], b = points[k + 1];
    hint = mesh.cdt.locate(to_point(a), hint);
    if (!mesh.walkable(hint)) {
      pinch.clearance = 0.0;
      pinch.in_free_space = false;
      return pinch;
    }
    NearestObstacle obstacle;
    const double d = obstacle_distance(mesh, hint, a, b, pinch.clearance, &obstacle);
    if (d < pinch.clearance) {
      const Vec2 on_path = closest_on_segment(obstacle.point, a, b);
      pinch = {d, obstacle, on_path, b - a, along + distance(a, on_path), true};
    }
    along += distance(a, b);
  }
  if (pinch.clearance == reach && pinch.in_free_space)
    pinch.clearance = std::numeric_limits<double>::infinity();
  return pinch;
}

/// Where `points` come nearest to the obstacles. A path that wraps a corner
/// touches its circle, so for a disc of `radius` the walk first looks only a
/// little beyond it, and further only for a path that met nothing so near.
Pinch find_pinch(const NavMeshState& mesh, const std::vector<Vec2>& points, double radius) {
  const Pinch near = find_pinch_within(mesh, points, 2 * radius + 0.1);
  if (near.clearance < std::numeric_limits<double>::infinity()) return near;
  return find_pinch_within(mesh, points, std::numeric_limits<double>::infinity());
}

/// An obstacle point outside the channel that its funnel path came too near
/// to: it becomes one more corner for the funnel to wrap (the query-time
/// counterpart of refining LCT's disturbances).
struct ExtraCorner {
  std::size_t face;  ///< Index of the channel face where the path came near it.
  double along;      ///< How far along the path that was.
  Vec2 point;
  bool left;     ///< On the walker's left.
  Vec2 heading;  ///< The path's direction there.
};

/// The channel's portals with a portal at each extra corner, placed in the
/// face where it was met. Its other end is a vertex of that face on the
/// other side (both ends of the portal beside it are); a channel of one face
/// has no such vertex (start and goal lie on the same side of each of its
/// edges), so there it is a point straight across the path `across` away,
/// beyond the domain by more than r: the funnel never has to wrap it.
std::vector<Portal> portals_with(const Channel& channel, std::vector<ExtraCorner> extra,
                                 double across) {
  std::sort(extra.begin(), extra.end(), [](const ExtraCorner& a, const ExtraCorner& b) {
    return std::tie(a.face, a.along) < std::tie(b.face, b.along);
  });
  const std::vector<Portal>& portals = channel.portals;
  std::vector<Portal> out;
  std::size_t k = 0;
  for (std::size_t i = 0; i <= portals.size(); ++i) {
    for (; k < extra.size() && extra[k].face == i; ++k) {
      const ExtraCorner& e = extra[k];
      const Vec2 to_left = (across / length(e.heading)) * perp(e.heading);
      const Portal beside = portals.empty() ? Portal{e.point + to_left, e.point - to_left}
                                            : portals[i > 0 ? i - 1 : 0];
      out.push_back(e.left ? Portal{e.point, beside.right} : Portal{beside.left, e.point});
    }
    if (i < portals.size()) out.push_back(portals[i]);
  }
  return out;
}

/// Index of the channel face nearest to `p` (the one holding it, up to rounding).
std::size_t face_index(const Channel& channel, Vec2 p) {
  std::size_t best = 0;
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < channel.faces.size(); ++i) {
    const Face f = channel.faces[i];
    double gap = 0.0;
    for (int e = 0; e < 3; ++e) {
      const Vec2 a = to_vec(f->vertex(Cdt::ccw(e))->point()),
                 b = to_vec(f->vertex(Cdt::cw(e))->point());
      if (cross(b - a, p - a) < 0) gap = std::max(gap, distance_to_segment(p, a, b));
    }
    if (gap < best_gap) {
      best_gap = gap;
      best = i;
    }
  }
  return best;
}

constexpr int kMaxExtraCorners = 16;
/// The finest arc sampling a squeeze is retried with. [m]
constexpr double kFinestArcTolerance = 1e-6;

/// What trying one channel gave.
enum class ChannelOutcome {
  kClear,      ///< A clear path shorter than the best so far.
  kLonger,     ///< Its path, as the search's bound foresaw, is no shorter than the best.
  kMisjudged,  ///< Too narrow after all, or made longer by obstacles beside it.
};

/// The shortest path through `channel` that clears the radius, wrapping
/// obstacles beside the channel as they turn up, if it is shorter than
/// `give_up_length`.
ChannelOutcome clear_path(const NavMeshState& mesh, const PathQuery& q, const Channel& channel,
                          double give_up_length, std::vector<Vec2>& points, double& clearance) {
  std::vector<ExtraCorner> extra;
  double tolerance = q.arc_tolerance;
  const double across = distance(mesh.min_corner, mesh.max_corner) + 2 * q.radius;
  bool strict_ends = false;  // the funnel's exact end check (channel_funnel.hpp)
  for (int pass = 0; pass <= kMaxExtraCorners + 1; ++pass) {
    FunnelPath path = funnel(q.from, q.to, portals_with(channel, extra, across), q.radius,
                             tolerance, strict_ends);
    if (!path.ok) return ChannelOutcome::kMisjudged;
    if (polyline_length(path.points) >= give_up_length)
      return extra.empty() ? ChannelOutcome::kLonger : ChannelOutcome::kMisjudged;
    const Pinch pinch = find_pinch(mesh, path.points, q.radius);
    if (pinch.clearance >= q.radius - kClearanceSlack) {
      points = std::move(path.points);
      clearance = pinch.clearance;
      return ChannelOutcome::kClear;
    }
    if (!pinch.in_free_space) return ChannelOutcome::kMisjudged;
    // Arcs are sampled outside their circles; in a squeeze that bulge alone
    // can come too near the far side, so sample finer before looking for
    // a missed obstacle.
    if (pinch.clearance > q.radius - tolerance && tolerance > kFinestArcTolerance) {
      tolerance = std::max(0.1 * tolerance, kFinestArcTolerance);
      continue;
    }
    // Near an edge, its ends are the corners to wrap (its foot slides along
    // as the path bends); the foot itself only once both ends are in.
    const NearestObstacle& near = pinch.obstacle;
    const bool left = cross(pinch.heading, near.point - pinch.path_point) > 0;
    auto known = [&](Vec2 p) {
      return std::any_of(extra.begin(), extra.end(),
                         [&](const ExtraCorner& c) { return c.point == p; });
    };
    const Vec2 candidates[3] = {near.edge_from, near.edge_to, near.point};
    const Vec2* corner = std::find_if(std::begin(candidates), std::end(candidates),
                                      [&](Vec2 p) { return !known(p); });
    if (corner == std::end(candidates)) {
      // No progress. The funnel's lenient end check can cause this: it takes
      // a corner that ends a portal to cross it on its arc where a tangent
      // crosses it, and so never checks the portal's other end, which is the
      // obstacle met again. Once more with the exact check; if that makes no
      // progress either, the channel is given up.
      if (strict_ends) return ChannelOutcome::kMisjudged;
      strict_ends = true;
      continue;
    }
    extra.push_back({face_index(channel, *corner), pinch.along, *corner, left, pinch.heading});
  }
  return ChannelOutcome::kMisjudged;
}

/// Hash of a channel by its faces.
struct ChannelHash {
  std::size_t operator()(const std::vector<const void*>& faces) const {
    std::size_t h = faces.size();
    for (const void* f : faces) h = h * 1000003u ^ std::hash<const void*>()(f);
    return h;
  }
};

}  // namespace

PathResult NavMesh::find_path(const PathQuery& q) const {
  if (!in_world(q.from) || !in_world(q.to))
    throw std::invalid_argument(
        "find_path: start and goal must be finite coordinates within 1e9 m");
  if (!(q.radius >= 0) || !std::isfinite(q.radius))
    throw std::invalid_argument("find_path: radius must be a finite number >= 0");
  if (!(q.arc_tolerance > 0) || !std::isfinite(q.arc_tolerance))
    throw std::invalid_argument("find_path: arc_tolerance must be a finite number > 0");
  const NavMeshState& m = *impl_;
  PathResult result;
  if (!m.in_domain(q.from) || !m.in_domain(q.to)) {
    result.status = PathStatus::kOutside;
    return result;
  }
  const Face start = m.cdt.locate(to_point(q.from), m.hints.near(to_point(q.from))),
             goal = m.cdt.locate(to_point(q.to), m.hints.near(to_point(q.to)));
  auto blocked = [&](Face f, Vec2 p) {
    return !m.walkable(f) || obstacle_distance(m, f, p, p, q.radius) < q.radius;
  };
  if (blocked(start, q.from)) {
    result.status = PathStatus::kStartBlocked;
    return result;
  }
  if (blocked(goal, q.to)) {
    result.status = PathStatus::kGoalBlocked;
    return result;
  }
  double best = std::numeric_limits<double>::infinity();
  auto keep = [&](std::vector<Vec2> points, double clearance) {
    best = polyline_length(points);
    result.status = PathStatus::kFound;
    result.length = best;
    result.min_clearance = clearance;
    result.points = std::move(points);
  };
  std::vector<Vec2> points;
  double clearance = 0.0;
  // Start and goal in one triangle: the straight line, or the way round
  // whatever stands in it, within the triangle (its own corners and the
  // obstacles beside it, wrapped as a channel's disturbances are). No
  // channel offers that: a channel leaves the triangle and enters it again.
  if (start == goal &&
      clear_path(m, q, Channel{{start}, {}}, best, points, clearance) == ChannelOutcome::kClear) {
    const bool straight = points.size() == 2;
    keep(std::move(points), clearance);
    if (straight) return result;  // nothing is shorter
  }
  Channel channel;
  bool misjudged = false;
  // Channels (by their faces) that gave no clear path: offered again, by the
  // retry or by another node over the same faces, they would give none again
  // (the best length only shrinks). No-path queries at r = 3 m on the 10k
  // scene offer the same failing channels to both searches.
  std::unordered_set<std::vector<const void*>, ChannelHash> failed;
  double kept_bound = std::numeric_limits<double>::infinity();  // of the best path's channel
  for (const int rivals : {0, kRivalsOnRetry}) {
    ChannelSearch search(m, q, start, goal, rivals);
    double bound = 0.0;
    while (search.next(channel, best / (1 + kLengthTolerance), bound)) {
      std::vector<const void*> faces;
      for (const Face f : channel.faces) faces.push_back(&*f);
      if (failed.count(faces)) continue;
      switch (clear_path(m, q, channel, best, points, clearance)) {
        case ChannelOutcome::kClear:
          keep(std::move(points), clearance);
          kept_bound = bound;
          break;
        case ChannelOutcome::kLonger:
          failed.insert(std::move(faces));
          break;
        case ChannelOutcome::kMisjudged:
          misjudged = true;
          failed.insert(std::move(faces));
          break;
      }
    }
    if (!misjudged && best <= kept_bound * (1 + kRelaxedTrust)) break;
  }
  return result;  // kNoPath unless a channel gave a path
}

}  // namespace footfall
