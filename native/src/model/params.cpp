// Footfall — validation of the parameter structs, from their tables.
#include "footfall/model/params.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "model/param_checks.hpp"

namespace footfall {
namespace {

template <class S>
void validate_struct(const S& params, const std::string& path);

// Each kind of table entry: its own checks.
template <class S>
struct FieldValidator {
  const S& params;
  const std::string& path;

  template <class T>
  void operator()(const ScalarParam<S, T>& field) const {
    const std::string name = path + "." + field.name;
    detail::check_range(params, static_cast<double>(params.*field.member), field.range, name);
  }
  template <class N>
  void operator()(const NestedParam<S, N>& field) const {
    validate_struct(params.*field.member, path + "." + field.name);
  }
  void operator()(const NumberListParam<S>& field) const {
    const std::vector<double>& list = params.*field.member;
    detail::check_count(list.size(), field.min_count, field.max_count, field.item_noun,
                        path + "." + field.name);
    for (std::size_t i = 0; i < list.size(); ++i)
      detail::check_range(params, list[i], field.range,
                          path + "." + field.name + "[" + std::to_string(i) + "]");
  }
  template <class E>
  void operator()(const StructListParam<S, E>& field) const {
    const std::vector<E>& list = params.*field.member;
    detail::check_count(list.size(), field.min_count, field.max_count, field.item_noun,
                        path + "." + field.name);
    for (std::size_t i = 0; i < list.size(); ++i)
      validate_struct(list[i], path + "." + field.name + "[" + std::to_string(i) + "]");
  }
};

template <class S>
void validate_struct(const S& params, const std::string& path) {
  for_each_param<S>(FieldValidator<S>{params, path});
}

}  // namespace

void validate(const CharacterParams& params, const std::string& path) {
  validate_struct(params, path);
}

void validate(const PlannerParams& params, const std::string& path) {
  validate_struct(params, path);
}

CharacterParams scaled(const CharacterParams& character, double scale) {
  CharacterParams c = character;
  const double pace = std::sqrt(scale);
  for (double* length : {&c.com_height, &c.foot_offset, &c.torso_width, &c.torso_radius, &c.shoulder_radius,
                         &c.foot_radius, &c.body_height, &c.shoulder_width, &c.chest_depth, &c.arm_swing_width,
                         &c.arm_radius, &c.leg_radius, &c.walk_clearance, &c.arms_in_clearance,
                         &c.side_step_clearance, &c.max_step_up, &c.max_step_down, &c.sole_length,
                         &c.sole_width})
    *length *= scale;
  for (double* speed : {&c.preferred_speed, &c.side_step_speed}) *speed *= pace;
  c.preferred_step_duration *= pace;
  for (FootLimits* foot : {&c.left, &c.right}) {
    foot->min_step_length *= scale;
    foot->max_step_length *= scale;
    foot->min_speed *= pace;
    foot->max_speed *= pace;
    foot->min_step_duration *= pace;
    foot->max_step_duration *= pace;
  }
  for (BehaviorMotion& motion : c.motions) {
    motion.cycle_duration *= pace;
    motion.speed *= pace;
    for (BodyPose& pose : motion.poses)
      for (Capsule& capsule : pose) capsule = {scale * capsule.a, scale * capsule.b, scale * capsule.radius};
  }
  return c;
}

}  // namespace footfall
