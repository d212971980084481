#include "animate/bone_structure.hpp"

#include <algorithm>
#include <set>
#include <tuple>

namespace footfall::animate {

namespace {

// The bones from `bone` up to, not including, its ancestor `stop`, nearest
// `stop` first; empty if `stop` is not an ancestor.
std::vector<std::string> chain_to(const std::string& bone, const std::string& stop, const Parents& parents) {
  std::vector<std::string> chain;
  std::optional<std::string> at = bone;
  while (at && *at != stop && chain.size() <= parents.size()) {
    chain.push_back(*at);
    const auto found = parents.find(*at);
    at = found == parents.end() ? std::nullopt : found->second;
  }
  if (!at || *at != stop) return {};
  std::reverse(chain.begin(), chain.end());
  return chain;
}

// A proper ancestor of both.
std::optional<std::string> common_ancestor(const std::string& a, const std::string& b, const Parents& parents) {
  const std::vector<std::string> above_a = ancestors(a, parents);
  const std::set<std::string> seen(above_a.begin() + 1, above_a.end());
  const std::vector<std::string> above_b = ancestors(b, parents);
  for (std::size_t i = 1; i < above_b.size(); ++i)
    if (seen.count(above_b[i])) return above_b[i];
  return std::nullopt;
}

}  // namespace

std::vector<std::string> ancestors(const std::string& bone, const Parents& parents) {
  std::vector<std::string> chain;
  std::optional<std::string> at = bone;
  while (at && std::find(chain.begin(), chain.end(), *at) == chain.end()) {
    chain.push_back(*at);
    const auto found = parents.find(*at);
    at = found == parents.end() ? std::nullopt : found->second;
  }
  return chain;
}

std::map<std::string, std::map<std::string, std::string>> limbs_from_shape(const std::vector<RigBone>& bones) {
  if (bones.empty()) return {};
  for (const RigBone& b : bones)
    if (!b.head || !b.tail) return {};
  Parents parents;
  std::map<std::string, const RigBone*> at;
  std::map<std::string, std::vector<std::string>> children;
  for (const RigBone& b : bones) {
    parents[b.name] = b.parent;
    at[b.name] = &b;
    children[b.name];
  }
  for (const RigBone& b : bones)
    if (b.parent && children.count(*b.parent)) children[*b.parent].push_back(b.name);
  std::vector<std::string> leaves;
  for (const RigBone& b : bones)
    if (children[b.name].empty()) leaves.push_back(b.name);
  const auto low = [&](const std::string& n) { return std::min(at[n]->head->z, at[n]->tail->z); };
  std::sort(leaves.begin(), leaves.end(),
            [&](const std::string& a, const std::string& b) { return std::make_tuple(low(a), a) < std::make_tuple(low(b), b); });
  // The legs: the lowest chain end, and the lowest other one whose chain
  // meets it three bones or more above both.
  std::optional<std::string> hips;
  std::vector<std::string> ends;
  for (std::size_t i = 1; i < leaves.size() && !hips; ++i) {
    const auto meet = common_ancestor(leaves[0], leaves[i], parents);
    if (meet && chain_to(leaves[0], *meet, parents).size() >= 3 && chain_to(leaves[i], *meet, parents).size() >= 3) {
      hips = meet;
      ends = {leaves[0], leaves[i]};
    }
  }
  if (!hips) return {};
  const std::vector<std::vector<std::string>> chains{chain_to(ends[0], *hips, parents), chain_to(ends[1], *hips, parents)};
  // The facing: heel to toe of both feet; left is up x facing.
  double fx = 0, fy = 0;
  for (const auto& chain : chains) {
    const RigBone& foot = *at[chain.size() >= 4 ? chain[chain.size() - 2] : chain.back()];
    fx += foot.tail->x - foot.head->x;
    fy += foot.tail->y - foot.head->y;
  }
  const Vec3 origin = *at[*hips]->head;
  const auto leftward = [&](const std::string& name) {
    const Vec3 tail = *at[name]->tail;
    return (tail.x - origin.x) * -fy + (tail.y - origin.y) * fx;
  };
  std::map<std::string, std::map<std::string, std::string>> found{{"left", {}}, {"right", {}}};
  for (const auto& chain : chains) {
    const std::string side = leftward(chain.back()) > 0 ? "left" : "right";
    const std::vector<std::string> roles = chain.size() >= 4 ? std::vector<std::string>{"thigh", "shin", "foot", "toe"}
                                                             : std::vector<std::string>{"thigh", "shin", "foot"};
    for (std::size_t k = 0; k < roles.size(); ++k) found[side][roles[k]] = chain[chain.size() - roles.size() + k];
  }
  if (found["left"].empty() || found["right"].empty()) return {};  // both legs on one side: the facing is unclear
  // The arms: the bones reaching farthest to either side, off the legs.
  std::set<std::string> in_legs(chains[0].begin(), chains[0].end());
  in_legs.insert(chains[1].begin(), chains[1].end());
  std::vector<std::string> rest;
  for (const RigBone& b : bones)
    if (!in_legs.count(b.name) && b.name != *hips) rest.push_back(b.name);
  if (rest.empty()) return found;
  std::string left_end = rest[0], right_end = rest[0];
  for (const std::string& name : rest) {
    if (leftward(name) > leftward(left_end)) left_end = name;
    if (leftward(name) < leftward(right_end)) right_end = name;
  }
  const auto chest = common_ancestor(left_end, right_end, parents);
  if (!chest || leftward(left_end) <= 0 || leftward(right_end) >= 0) return found;
  for (const auto& [side, end] : {std::make_pair(std::string("left"), left_end), std::make_pair(std::string("right"), right_end)}) {
    const std::vector<std::string> chain = chain_to(end, *chest, parents);
    if (chain.empty()) continue;
    auto hand = std::find_if(chain.begin(), chain.end(), [&](const std::string& b) { return children[b].size() > 1; });
    if (hand == chain.end()) hand = chain.end() - 1;
    const std::size_t upto = static_cast<std::size_t>(hand - chain.begin()) + 1;
    if (upto >= 3) {
      found[side]["upper_arm"] = chain[upto - 3];
      found[side]["forearm"] = chain[upto - 2];
      found[side]["hand"] = chain[upto - 1];
    }
  }
  return found;
}

}  // namespace footfall::animate
