// Footfall — reading a glTF accessor's values, whatever their component type,
// stride or sparse substitution, checked against the buffers' bounds.
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace footfall::animate {

/// The accessor's values as doubles, `count * components` of them; integer
/// components as they are, or mapped to [0, 1] / [-1, 1] when normalized.
/// std::invalid_argument "accessors[i]: what is wrong" for an accessor that
/// reaches outside its buffer or has no data.
std::vector<double> accessor_values(const tinygltf::Model& model, int accessor);

/// The number of components of the accessor's type (SCALAR 1 ... MAT4 16).
int component_count(const tinygltf::Accessor& accessor);

}  // namespace footfall::animate
