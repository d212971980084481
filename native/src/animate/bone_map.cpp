// Bones by name and hierarchy: limbs by a side marker and a base name among
// synonyms, the trunk where the limbs meet; limbs whose names say nothing
// from the skeleton's shape (bone_structure).
#include "footfall/animate/bone_map.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <tuple>

#include "animate/bone_structure.hpp"

namespace footfall {

namespace {

using animate::ancestors;
using animate::Parents;

const char* const kCenterRoles[] = {"hips", "spine", "chest", "neck", "head"};
const char* const kLimbRoles[] = {"upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe"};
const char* const kSides[] = {"left", "right"};

// Base names after normalisation (lower case, no separators).
const std::map<std::string, std::set<std::string>> kLimbSynonyms = {
    {"upper_arm", {"upperarm", "arm", "uparm", "armupper"}},
    {"forearm", {"forearm", "lowerarm", "elbow", "armlower"}},
    {"hand", {"hand", "wrist"}},
    {"thigh", {"thigh", "upleg", "upperleg", "legupper", "thighbone"}},
    {"shin", {"shin", "calf", "leg", "lowerleg", "knee", "leglower"}},
    {"foot", {"foot", "ankle"}},
    {"toe", {"toe", "toes", "toebase", "ball", "toe0", "toes0"}},
};
const std::set<std::string> kNeckNames = {"neck", "neck01", "neck1"};
const std::set<std::string> kHeadNames = {"head"};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::string normalise(const std::string& text) {
  std::string out;
  for (const char c : lower(text))
    if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) out += c;
  return out;
}

bool is_separator(char c) { return c == '.' || c == '_' || c == '-' || c == ' '; }

// The bone of `side` whose base name is one of `names`; nearest the root wins.
std::optional<std::string> by_name(const std::vector<RigBone>& bones, const Parents& parents,
                                   const std::string& side, const std::set<std::string>& names) {
  std::optional<std::string> best;
  std::size_t best_depth = 0;
  for (const RigBone& bone : bones) {
    const auto [bone_side, base] = split_side(bone.name);
    if (bone_side != side || !names.count(base)) continue;
    const std::size_t depth = ancestors(bone.name, parents).size();
    if (!best || std::tie(depth, bone.name) < std::tie(best_depth, *best)) {
      best = bone.name;
      best_depth = depth;
    }
  }
  return best;
}

// The lowest common proper ancestor of two bones.
std::optional<std::string> meeting_point(const std::string& a, const std::string& b, const Parents& parents) {
  const std::vector<std::string> above_a = ancestors(a, parents);
  const std::vector<std::string> above_b = ancestors(b, parents);
  const std::set<std::string> b_set(above_b.begin() + 1, above_b.end());
  for (std::size_t i = 1; i < above_a.size(); ++i)
    if (b_set.count(above_a[i])) return above_a[i];
  return std::nullopt;
}

double bone_length(const RigBone& bone) { return length(*bone.tail - *bone.head); }

// True if `child` starts nearer `bone`'s tail than half its length (or the
// rest geometry is not known).
bool continues(const RigBone& bone, const RigBone& child) {
  if (!bone.tail || !child.head) return true;
  return length(*child.head - *bone.tail) < 0.5 * bone_length(bone);
}

std::optional<std::string> given_role(const std::map<std::string, std::string>& given, const std::string& role) {
  const auto found = given.find(role);
  if (found == given.end() || found->second.empty()) return std::nullopt;
  return found->second;
}

}  // namespace

std::pair<std::string, std::string> split_side(const std::string& full) {
  const std::size_t colon = full.rfind(':');
  const std::string name = colon == std::string::npos ? full : full.substr(colon + 1);
  const std::string low = lower(name);
  // "base.L", "base_right": the first separator after which only the side is left.
  for (std::size_t i = 1; i + 1 < name.size(); ++i) {
    if (!is_separator(name[i])) continue;
    const std::string side = low.substr(i + 1);
    if (side == "l" || side == "r" || side == "left" || side == "right")
      return {side[0] == 'l' ? "left" : "right", normalise(name.substr(0, i))};
  }
  // "LeftArm", "L_Arm": a bare "L" or "R" needs a separator, or "Leg" would
  // read as the left "eg".
  for (const std::string word : {"left", "right", "l", "r"}) {
    if (low.size() <= word.size() || low.compare(0, word.size(), word) != 0) continue;
    const std::string rest = name.substr(word.size());
    const bool separated = rest.size() > 1 && is_separator(rest[0]);
    if (word.size() > 1 || separated)
      return {word[0] == 'l' ? "left" : "right", normalise(separated ? rest.substr(1) : rest)};
    return {"", normalise(name)};
  }
  return {"", normalise(name)};
}

BoneDetection detect_bones(const std::vector<RigBone>& bones, const std::map<std::string, std::string>& given) {
  Parents parents;
  for (const RigBone& bone : bones) parents[bone.name] = bone.parent;
  BoneDetection result;
  std::optional<std::map<std::string, std::map<std::string, std::string>>> shape;  // found when first wanted
  for (const std::string side : kSides) {
    for (const std::string role : kLimbRoles) {
      const std::string key = side + "." + role;
      std::optional<std::string> found = given_role(given, key);
      if (!found) found = by_name(bones, parents, side, kLimbSynonyms.at(role));
      if (!found) {
        if (!shape) shape = animate::limbs_from_shape(bones);
        const auto limbs = shape->find(side);
        if (limbs != shape->end() && limbs->second.count(role)) found = limbs->second.at(role);
      }
      if (found)
        result.roles[key] = *found;
      else
        result.missing.push_back(key);
    }
  }
  const auto both = [&](const std::string& role) {
    return std::make_pair(result.roles.find("left." + role), result.roles.find("right." + role));
  };
  const auto thighs = both("thigh"), arms = both("upper_arm");
  const auto none = result.roles.end();
  std::optional<std::string> hips, chest, spine, neck, head;
  if (thighs.first != none && thighs.second != none)
    hips = meeting_point(thighs.first->second, thighs.second->second, parents);
  if (arms.first != none && arms.second != none)
    chest = meeting_point(arms.first->second, arms.second->second, parents);
  if (hips && chest) {
    const std::vector<std::string> path = ancestors(*chest, parents);  // chest ... root
    const auto at_hips = std::find(path.begin(), path.end(), *hips);
    const auto below_chest = static_cast<std::size_t>(at_hips - path.begin());  // chest ... first bone above the hips
    if (at_hips != path.end() && below_chest > 1) spine = path[below_chest - 1];
  }
  head = by_name(bones, parents, "", kHeadNames);
  neck = by_name(bones, parents, "", kNeckNames);
  if (chest && !head) {
    // The chain that rises from the chest, neither arm's: the neck its first
    // bone, the head where it ends or branches (into a face's bones), as
    // Rigify's spine.004 to spine.006 are.
    std::set<std::string> arm_chains;
    for (const auto& arm : {arms.first, arms.second})
      if (arm != none)
        for (const std::string& b : ancestors(arm->second, parents)) arm_chains.insert(b);
    std::vector<const RigBone*> above;
    for (const RigBone& b : bones)
      if (b.parent == chest && !arm_chains.count(b.name)) above.push_back(&b);
    const bool shaped = std::all_of(above.begin(), above.end(), [](const RigBone* b) { return b->head && b->tail; });
    if (above.size() > 1 && shaped) {
      const auto rise = [](const RigBone* b) {
        const double l = bone_length(*b);
        return (b->tail->z - b->head->z) / (l != 0 ? l : 1.0);
      };
      const RigBone* steepest = above[0];
      for (const RigBone* b : above)
        if (rise(b) > rise(steepest)) steepest = b;
      above = {steepest};
    }
    if (above.size() == 1) {
      std::vector<const RigBone*> chain{above[0]};
      while (chain.size() <= bones.size()) {
        std::vector<const RigBone*> next;
        for (const RigBone& b : bones)
          if (b.parent == chain.back()->name) next.push_back(&b);
        // Only a bone that goes on from the last one's tail (Rigify's face
        // bone starts back at the head's root, inside it).
        if (next.size() != 1 || !continues(*chain.back(), *next[0])) break;
        chain.push_back(next[0]);
      }
      if (chain.size() > 1) neck = chain.front()->name;
      else neck = std::nullopt;
      head = chain.back()->name;
    }
  }
  if (!neck && head) {
    const auto parent = parents.find(*head);
    if (parent != parents.end() && parent->second && parent->second != chest) neck = parent->second;
  }
  const std::optional<std::string> found[] = {hips, spine, chest, neck, head};
  for (std::size_t i = 0; i < 5; ++i) {
    const std::optional<std::string> bone = given_role(given, kCenterRoles[i]) ? given_role(given, kCenterRoles[i]) : found[i];
    if (bone)
      result.roles[kCenterRoles[i]] = *bone;
    else
      result.missing.push_back(kCenterRoles[i]);
  }
  return result;
}

}  // namespace footfall
