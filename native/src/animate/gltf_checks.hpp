// Footfall — a glTF document's references checked before anything follows
// them: tinygltf parses indices without checking that what they name exists.
#pragma once

#include <tiny_gltf.h>

#include <string>

namespace footfall::animate {

/// std::invalid_argument "PATH: nodes[3].mesh: 7 is not a mesh (there are
/// 1)" for the first reference to nothing.
void check_references(const tinygltf::Model& model, const std::string& path);

}  // namespace footfall::animate
