#include "animate/gltf_checks.hpp"

#include <stdexcept>

namespace footfall::animate {

namespace {

class References {
 public:
  References(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

  /// `index` names one of `count` items of `kind`; -1 (none) is allowed where `optional`.
  void check(int index, std::size_t count, const char* kind, const std::string& field, bool optional = true) const {
    if ((optional && index == -1) || (index >= 0 && static_cast<std::size_t>(index) < count)) return;
    throw std::invalid_argument(path_ + ": " + field + ": " + std::to_string(index) + " is not " + kind +
                                " (there are " + std::to_string(count) + ")");
  }
  void accessor(int index, const std::string& field, bool optional = true) const {
    check(index, model_.accessors.size(), "an accessor", field, optional);
  }
  void view(int index, const std::string& field, bool optional = true) const {
    check(index, model_.bufferViews.size(), "a bufferView", field, optional);
  }
  void texture(int index, const std::string& field) const {
    check(index, model_.textures.size(), "a texture", field);
  }

 private:
  const tinygltf::Model& model_;
  const std::string& path_;
};

std::string at(const char* array, std::size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

}  // namespace

void check_references(const tinygltf::Model& m, const std::string& path) {
  const References refs(m, path);
  for (std::size_t i = 0; i < m.bufferViews.size(); ++i)
    refs.check(m.bufferViews[i].buffer, m.buffers.size(), "a buffer", at("bufferViews", i) + ".buffer", false);
  for (std::size_t i = 0; i < m.accessors.size(); ++i) {
    const tinygltf::Accessor& a = m.accessors[i];
    refs.view(a.bufferView, at("accessors", i) + ".bufferView");
    if (a.sparse.isSparse) {
      refs.view(a.sparse.indices.bufferView, at("accessors", i) + ".sparse.indices.bufferView", false);
      refs.view(a.sparse.values.bufferView, at("accessors", i) + ".sparse.values.bufferView", false);
    }
  }
  for (std::size_t i = 0; i < m.images.size(); ++i) refs.view(m.images[i].bufferView, at("images", i) + ".bufferView");
  for (std::size_t i = 0; i < m.textures.size(); ++i) {
    refs.check(m.textures[i].source, m.images.size(), "an image", at("textures", i) + ".source");
    refs.check(m.textures[i].sampler, m.samplers.size(), "a sampler", at("textures", i) + ".sampler");
  }
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const tinygltf::Material& material = m.materials[i];
    const std::string field = at("materials", i);
    refs.texture(material.pbrMetallicRoughness.baseColorTexture.index, field + ".baseColorTexture");
    refs.texture(material.pbrMetallicRoughness.metallicRoughnessTexture.index, field + ".metallicRoughnessTexture");
    refs.texture(material.normalTexture.index, field + ".normalTexture");
    refs.texture(material.occlusionTexture.index, field + ".occlusionTexture");
    refs.texture(material.emissiveTexture.index, field + ".emissiveTexture");
  }
  for (std::size_t i = 0; i < m.meshes.size(); ++i)
    for (std::size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = m.meshes[i].primitives[p];
      const std::string field = at("meshes", i) + "." + at("primitives", p);
      for (const auto& [name, accessor] : primitive.attributes) refs.accessor(accessor, field + ".attributes." + name, false);
      refs.accessor(primitive.indices, field + ".indices");
      refs.check(primitive.material, m.materials.size(), "a material", field + ".material");
      for (std::size_t t = 0; t < primitive.targets.size(); ++t)
        for (const auto& [name, accessor] : primitive.targets[t]) refs.accessor(accessor, field + "." + at("targets", t) + "." + name, false);
    }
  for (std::size_t i = 0; i < m.skins.size(); ++i) {
    const tinygltf::Skin& skin = m.skins[i];
    refs.accessor(skin.inverseBindMatrices, at("skins", i) + ".inverseBindMatrices");
    refs.check(skin.skeleton, m.nodes.size(), "a node", at("skins", i) + ".skeleton");
    for (std::size_t j = 0; j < skin.joints.size(); ++j)
      refs.check(skin.joints[j], m.nodes.size(), "a node", at("skins", i) + "." + at("joints", j), false);
  }
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const tinygltf::Node& node = m.nodes[i];
    refs.check(node.mesh, m.meshes.size(), "a mesh", at("nodes", i) + ".mesh");
    refs.check(node.skin, m.skins.size(), "a skin", at("nodes", i) + ".skin");
    for (std::size_t c = 0; c < node.children.size(); ++c)
      refs.check(node.children[c], m.nodes.size(), "a node", at("nodes", i) + "." + at("children", c), false);
  }
  for (std::size_t i = 0; i < m.scenes.size(); ++i)
    for (std::size_t n = 0; n < m.scenes[i].nodes.size(); ++n)
      refs.check(m.scenes[i].nodes[n], m.nodes.size(), "a node", at("scenes", i) + "." + at("nodes", n), false);
  for (std::size_t i = 0; i < m.animations.size(); ++i) {
    const tinygltf::Animation& animation = m.animations[i];
    for (std::size_t s = 0; s < animation.samplers.size(); ++s) {
      refs.accessor(animation.samplers[s].input, at("animations", i) + "." + at("samplers", s) + ".input", false);
      refs.accessor(animation.samplers[s].output, at("animations", i) + "." + at("samplers", s) + ".output", false);
    }
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
      const std::string field = at("animations", i) + "." + at("channels", c);
      refs.check(animation.channels[c].sampler, animation.samplers.size(), "a sampler", field + ".sampler", false);
      refs.check(animation.channels[c].target_node, m.nodes.size(), "a node", field + ".target.node");
    }
  }
}

}  // namespace footfall::animate
