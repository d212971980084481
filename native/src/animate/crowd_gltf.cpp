// The crowd as one .glb: the rig's meshes, materials and textures once; per
// agent a copy of its nodes, a skin and an animation.
#include "footfall/animate/crowd_gltf.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

#include "animate/agent_motion.hpp"
#include "animate/rig_data.hpp"
#include "io/atomic_file.hpp"
#include "util/quoted.hpp"

namespace footfall {

namespace {

using animate::RigData;
using animate::Trs;
using detail::user_text;

constexpr double kComAboveHips = 1.05;  // the COM stands about 5 % above the hip joints
constexpr double kStill = 1e-6;         // a channel this close to its rest at every frame is left out

class CrowdModel {
 public:
  explicit CrowdModel(const RigData& rig) : rig_(rig) {
    out_.asset.version = "2.0";
    out_.asset.generator = "Footfall";
    out_.buffers.emplace_back();
    out_.samplers = rig.model.samplers;
    out_.textures = rig.model.textures;
    out_.materials = rig.model.materials;
    for (const std::string& extension : rig.model.extensionsUsed)
      if (extension != "KHR_lights_punctual") out_.extensionsUsed.push_back(extension);
    for (tinygltf::Image image : rig.model.images) {
      if (image.bufferView >= 0) {
        image.bufferView = copy_view(image.bufferView);
      } else if (!image.image.empty()) {  // a data URI's bytes, now in the buffer
        image.bufferView = add_view(image.image.data(), image.image.size(), -1);
        image.image.clear();
      }
      out_.images.push_back(std::move(image));
    }
    out_.scenes.emplace_back();
    out_.scenes[0].name = "Crowd";
    out_.defaultScene = 0;
  }

  /// The agent's nodes under one named after it, scaled by `scale` (the
  /// rig's size to the agent's); returns rig node -> output node.
  std::vector<int> add_agent_nodes(const std::string& name, double scale) {
    std::vector<int> copy(rig_.model.nodes.size(), -1);
    const int root = static_cast<int>(out_.nodes.size());
    out_.nodes.emplace_back();
    out_.nodes[root].name = name;
    if (scale != 1.0) out_.nodes[root].scale = {scale, scale, scale};
    out_.scenes[0].nodes.push_back(root);
    const std::function<int(int)> add = [&](int node) {
      const int index = static_cast<int>(out_.nodes.size());
      copy[node] = index;
      out_.nodes.emplace_back();
      const tinygltf::Node& source = rig_.model.nodes[node];
      tinygltf::Node& target = out_.nodes[index];
      target.name = source.name;
      set_trs(target, rig_.rest_trs[node]);
      target.weights = source.weights;
      if (source.mesh >= 0) target.mesh = copy_mesh(source.mesh);
      std::vector<int> children;
      for (int child : source.children) children.push_back(add(child));
      out_.nodes[index].children = children;
      return index;
    };
    for (int node : rig_.scene_roots) {
      const int child = add(node);  // before indexing: adding nodes moves them
      out_.nodes[root].children.push_back(child);
    }
    // A skin of its own per skin of the rig, over the agent's joints.
    std::map<int, int> skins;
    for (std::size_t node = 0; node < copy.size(); ++node) {
      const int skin = rig_.model.nodes[node].skin;
      if (copy[node] < 0 || skin < 0) continue;
      if (!skins.count(skin)) {
        tinygltf::Skin own = rig_.model.skins[skin];
        own.name = name + " " + own.name;
        for (int& joint : own.joints) joint = copy[joint];
        if (own.skeleton >= 0) own.skeleton = copy[own.skeleton];
        if (own.inverseBindMatrices >= 0) own.inverseBindMatrices = copy_accessor(own.inverseBindMatrices);
        skins[skin] = static_cast<int>(out_.skins.size());
        out_.skins.push_back(std::move(own));
      }
      out_.nodes[copy[node]].skin = skins[skin];
    }
    agent_roots_.push_back(root);
    return copy;
  }

  /// Float data as a new accessor with its min and max (an animation's).
  int add_floats(const std::vector<float>& values, int components) {
    pad_animation_data();
    tinygltf::Accessor accessor;
    accessor.byteOffset = animation_data_.size();
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.count = values.size() / components;
    accessor.type = components == 1 ? TINYGLTF_TYPE_SCALAR : components == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
    accessor.minValues.assign(components, 1e300);
    accessor.maxValues.assign(components, -1e300);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const auto c = i % components;
      accessor.minValues[c] = std::min(accessor.minValues[c], static_cast<double>(values[i]));
      accessor.maxValues[c] = std::max(accessor.maxValues[c], static_cast<double>(values[i]));
    }
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    animation_data_.insert(animation_data_.end(), bytes, bytes + values.size() * sizeof(float));
    animation_accessors_.push_back(static_cast<int>(out_.accessors.size()));
    out_.accessors.push_back(std::move(accessor));
    return static_cast<int>(out_.accessors.size()) - 1;
  }

  tinygltf::Model& model() { return out_; }
  int last_root() const { return agent_roots_.back(); }

  /// The finished document: the animation data after the rig's, in one view.
  tinygltf::Model& finish() {
    std::vector<unsigned char>& data = out_.buffers[0].data;
    const int view = add_view(animation_data_.data(), animation_data_.size(), -1);
    for (int accessor : animation_accessors_) out_.accessors[accessor].bufferView = view;
    data.resize((data.size() + 3) / 4 * 4, 0);
    return out_;
  }

 private:
  static void set_trs(tinygltf::Node& node, const Trs& trs) {
    node.translation = {trs.translation.x, trs.translation.y, trs.translation.z};
    node.rotation = {trs.rotation.x, trs.rotation.y, trs.rotation.z, trs.rotation.w};
    node.scale = {trs.scale.x, trs.scale.y, trs.scale.z};
  }

  void pad_animation_data() { animation_data_.resize((animation_data_.size() + 3) / 4 * 4, 0); }

  int add_view(const unsigned char* bytes, std::size_t size, int target, int stride = 0) {
    std::vector<unsigned char>& data = out_.buffers[0].data;
    data.resize((data.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.byteStride = static_cast<size_t>(stride);
    view.target = target;
    data.insert(data.end(), bytes, bytes + size);
    out_.bufferViews.push_back(view);
    return static_cast<int>(out_.bufferViews.size()) - 1;
  }

  int copy_view(int index) {
    if (const auto found = views_.find(index); found != views_.end()) return found->second;
    const tinygltf::BufferView& view = rig_.model.bufferViews.at(index);
    const std::vector<unsigned char>& data = rig_.model.buffers.at(view.buffer).data;
    if (view.byteOffset + view.byteLength > data.size())
      throw std::invalid_argument(rig_.path + ": bufferViews[" + std::to_string(index) + "] reaches outside its buffer");
    const int copied = add_view(data.data() + view.byteOffset, view.byteLength, view.target,
                                static_cast<int>(view.byteStride));
    out_.bufferViews[copied].name = view.name;
    views_[index] = copied;
    return copied;
  }

  int copy_accessor(int index) {
    if (const auto found = accessors_.find(index); found != accessors_.end()) return found->second;
    tinygltf::Accessor accessor = rig_.model.accessors.at(index);
    if (accessor.bufferView >= 0) accessor.bufferView = copy_view(accessor.bufferView);
    if (accessor.sparse.isSparse) {
      accessor.sparse.indices.bufferView = copy_view(accessor.sparse.indices.bufferView);
      accessor.sparse.values.bufferView = copy_view(accessor.sparse.values.bufferView);
    }
    out_.accessors.push_back(std::move(accessor));
    return accessors_[index] = static_cast<int>(out_.accessors.size()) - 1;
  }

  int copy_mesh(int index) {
    if (const auto found = meshes_.find(index); found != meshes_.end()) return found->second;
    tinygltf::Mesh mesh = rig_.model.meshes.at(index);
    for (tinygltf::Primitive& primitive : mesh.primitives) {
      for (auto& attribute : primitive.attributes) attribute.second = copy_accessor(attribute.second);
      if (primitive.indices >= 0) primitive.indices = copy_accessor(primitive.indices);
      for (auto& target : primitive.targets)
        for (auto& attribute : target) attribute.second = copy_accessor(attribute.second);
    }
    out_.meshes.push_back(std::move(mesh));
    return meshes_[index] = static_cast<int>(out_.meshes.size()) - 1;
  }

  const RigData& rig_;
  tinygltf::Model out_;
  std::map<int, int> views_, accessors_, meshes_;  // rig index -> output index
  std::vector<unsigned char> animation_data_;
  std::vector<int> animation_accessors_;
  std::vector<int> agent_roots_;
};

void check_size(const Plan& plan, const AgentPlan& agent, const RigData& rig) {
  const double planned = character_of(agent, plan.character).com_height;
  const double standing = kComAboveHips * rig.hip_height * agent.scale;
  const double off = standing / planned - 1.0;
  if (std::abs(off) > kRigSizeTolerance) {
    std::ostringstream message;
    message.precision(2);
    message << std::fixed << "agent " << user_text(agent.name) << ": the rig " << user_text(rig.path)
            << " stands " << (off > 0 ? "+" : "") << std::setprecision(0) << 100 * off
            << " % off the character it was planned with (centre of mass " << std::setprecision(2)
            << standing << " m against " << planned << " m): plan with a character of this rig's size";
    throw std::invalid_argument(message.str());
  }
}

bool differs(const std::vector<Trs>& frames, const Trs& rest, int path) {
  for (const Trs& f : frames) {
    if (path == 0 && length(f.translation - rest.translation) > kStill) return true;
    if (path == 2 && length(f.scale - rest.scale) > kStill) return true;
    if (path == 1) {
      const animate::Quat& a = f.rotation;
      const animate::Quat& b = rest.rotation;
      if (1.0 - std::abs(a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z) > kStill) return true;
    }
  }
  return false;
}

// A sampler of `input` times and `output` values, and the channel that
// animates `path` of `node` with it.
void add_sampled(tinygltf::Animation& animation, int input, int output, const char* interpolation, int node,
                 const char* path) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = interpolation;
  tinygltf::AnimationChannel channel;
  channel.sampler = static_cast<int>(animation.samplers.size());
  channel.target_node = node;
  channel.target_path = path;
  animation.samplers.push_back(sampler);
  animation.channels.push_back(channel);
}

// One LINEAR channel of `node` from the motion's frames.
void add_channel(CrowdModel& crowd, tinygltf::Animation& animation, int input, int node,
                 const std::vector<Trs>& frames, int path) {
  std::vector<float> values;
  const int components = path == 1 ? 4 : 3;
  values.reserve(frames.size() * components);
  animate::Quat previous;
  for (const Trs& f : frames) {
    if (path == 1) {
      animate::Quat q = f.rotation;
      // Neighbouring keys on the same side of the sphere.
      if (q.w * previous.w + q.x * previous.x + q.y * previous.y + q.z * previous.z < 0) q = {-q.w, -q.x, -q.y, -q.z};
      previous = q;
      for (double v : {q.x, q.y, q.z, q.w}) values.push_back(static_cast<float>(v));
    } else {
      const Vec3 v = path == 0 ? f.translation : f.scale;
      for (double c : {v.x, v.y, v.z}) values.push_back(static_cast<float>(c));
    }
  }
  add_sampled(animation, input, crowd.add_floats(values, components), "LINEAR", node,
              path == 0 ? "translation" : path == 1 ? "rotation" : "scale");
}

}  // namespace

CrowdGltfSummary write_crowd_gltf(const Plan& plan, const Rig& rig, const std::string& path,
                                  const CrowdGltfOptions& options) {
  if (!(options.fps >= 1 && options.fps <= 240))
    throw std::invalid_argument("fps: expected a number from 1 to 240");
  const Ground ground(plan.ground);
  const RigData& data = rig.data();
  for (const AgentPlan& agent : plan.agents) check_size(plan, agent, data);
  double end = 0;
  for (const AgentPlan& agent : plan.agents) end = std::max(end, agent.end_time());
  const int frames = static_cast<int>(std::ceil(end * options.fps - 1e-9)) + 1;
  std::vector<double> times(frames);
  std::vector<float> key_times(frames);
  for (int f = 0; f < frames; ++f) {
    times[f] = f / options.fps;
    key_times[f] = static_cast<float>(times[f]);
  }

  CrowdModel crowd(data);
  const int input = crowd.add_floats(key_times, 1);
  for (const AgentPlan& agent : plan.agents) {
    const std::vector<int> copy = crowd.add_agent_nodes(agent.name, agent.scale);
    const animate::AgentMotion motion = animate::agent_motion(data, agent, character_of(agent, plan.character), ground, times, options.fps);
    tinygltf::Animation animation;
    animation.name = agent.name;
    for (std::size_t i = 0; i < motion.nodes.size(); ++i) {
      const int node = motion.nodes[i];
      for (int p = 0; p < 3; ++p)
        if ((node == data.hips && p < 2) || differs(motion.frames[i], data.rest_trs[node], p))
          add_channel(crowd, animation, input, copy[node], motion.frames[i], p);
    }
    if (agent.leaves) {
      // Gone from the first key after it has left: scaled to nothing.
      const float gone = static_cast<float>((std::floor(agent.end_time() * options.fps) + 1) / options.fps);
      const float scale = static_cast<float>(agent.scale);
      add_sampled(animation, crowd.add_floats({0.0f, gone}, 1), crowd.add_floats({scale, scale, scale, 0, 0, 0}, 3),
                  "STEP", crowd.last_root(), "scale");
    }
    crowd.model().animations.push_back(std::move(animation));
  }

  tinygltf::Model& model = crowd.finish();
  // A .glb states its length in 32 bits; the JSON that goes with the keys is
  // far smaller than this margin.
  constexpr std::uintmax_t kGlbLimit = 0xFFFFFFFFu, kJsonMargin = 256u << 20;
  const std::uintmax_t keys = model.buffers[0].data.size();
  if (keys > kGlbLimit - kJsonMargin)
    throw std::invalid_argument(
        path + ": the crowd's keys take " + std::to_string(keys >> 20) +
        " MiB, over the 4 GiB a .glb can hold: animate fewer agents, fewer keys a second "
        "(--fps), or a shorter plan");
  tinygltf::TinyGLTF writer;
  std::uintmax_t written = 0;
  // Streamed to the file: the model is not held a second and third time as text.
  detail::write_file_atomically(path, [&](std::ostream& stream) {
    const std::streampos begin = stream.tellp();
    if (!writer.WriteGltfSceneToStream(&model, stream, false, true))
      throw Error(path + ": the glTF could not be serialised");
    written = static_cast<std::uintmax_t>(stream.tellp() - begin);
  });
  CrowdGltfSummary summary;
  summary.agents = static_cast<int>(plan.agents.size());
  summary.frames = frames;
  summary.bytes = written;
  summary.clips = rig.clip_sources();
  return summary;
}

}  // namespace footfall
