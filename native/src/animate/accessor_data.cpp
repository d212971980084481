#include "animate/accessor_data.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace footfall::animate {

namespace {

[[noreturn]] void bad(int accessor, const std::string& message) {
  throw std::invalid_argument("accessors[" + std::to_string(accessor) + "]: " + message);
}

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

double component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double v = static_cast<double>(static_cast<std::int8_t>(*p));
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? v / 4294967295.0 : v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// Reads `count` elements of `components` components from a buffer view.
void read_view(const tinygltf::Model& model, int accessor, int view_index, std::size_t offset,
               std::size_t count, int components, int type, bool normalized, std::vector<double>& out) {
  if (view_index < 0 || view_index >= static_cast<int>(model.bufferViews.size()))
    bad(accessor, "its bufferView does not exist");
  const tinygltf::BufferView& view = model.bufferViews[view_index];
  if (view.buffer < 0 || view.buffer >= static_cast<int>(model.buffers.size()))
    bad(accessor, "its buffer does not exist");
  const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
  const std::size_t size = static_cast<std::size_t>(component_size(type));
  if (size == 0) bad(accessor, "unknown component type " + std::to_string(type));
  const std::size_t element = size * static_cast<std::size_t>(components);
  const std::size_t stride = view.byteStride > 0 ? view.byteStride : element;
  if (count > 0 && (view.byteOffset + view.byteLength > data.size() ||
                    offset + (count - 1) * stride + element > view.byteLength))
    bad(accessor, "reaches outside its buffer");
  out.resize(count * components);
  const unsigned char* base = data.data() + view.byteOffset + offset;
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c)
      out[i * components + c] = component(base + i * stride + c * size, type, normalized);
}

}  // namespace

int component_count(const tinygltf::Accessor& accessor) {
  const int n = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
  return n > 0 ? n : 0;
}

std::vector<double> accessor_values(const tinygltf::Model& model, int index) {
  if (index < 0 || index >= static_cast<int>(model.accessors.size())) bad(index, "does not exist");
  const tinygltf::Accessor& a = model.accessors[index];
  const int components = component_count(a);
  if (components == 0) bad(index, "unknown type");
  std::vector<double> values;
  if (a.bufferView >= 0) {
    read_view(model, index, a.bufferView, a.byteOffset, a.count, components, a.componentType,
              a.normalized, values);
  } else {
    values.assign(a.count * components, 0.0);
  }
  if (a.sparse.isSparse) {
    std::vector<double> indices, substitutes;
    const auto count = static_cast<std::size_t>(a.sparse.count);
    read_view(model, index, a.sparse.indices.bufferView, a.sparse.indices.byteOffset, count, 1,
              a.sparse.indices.componentType, false, indices);
    read_view(model, index, a.sparse.values.bufferView, a.sparse.values.byteOffset, count, components,
              a.componentType, a.normalized, substitutes);
    for (std::size_t i = 0; i < count; ++i) {
      const auto target = static_cast<std::size_t>(indices[i]);
      if (target >= a.count) bad(index, "a sparse index is out of range");
      for (int c = 0; c < components; ++c) values[target * components + c] = substitutes[i * components + c];
    }
  }
  return values;
}

}  // namespace footfall::animate
