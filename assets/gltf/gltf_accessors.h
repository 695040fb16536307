#pragma once
// Reading glTF accessors with every byte range checked against the buffer bytes tinygltf
// actually loaded: accessor inside its bufferView, bufferView inside its buffer, stride no
// smaller than an element, sparse indices inside the accessor. Accessors without a
// bufferView read as zeros (then sparse substitution), as the spec says, with a cap on their
// size so a lying count cannot allocate gigabytes. Errors are InputErrors of the form
// "<file>: <element>: <role> accessor 4 reads past the end of bufferView 2 (...)".
// Internal to pt_assets.
#include <cstdint>
#include <string>
#include <vector>

#include "assets/gltf/gltf_context.h"
#include "render/math/vec.h"

namespace pt {

// Where an accessor is read from, for messages: `element` is e.g. "meshes[0].primitives[1]"
// and `role` e.g. "indices" or "POSITION".
struct AccessorUse {
    const std::string& element;
    const std::string& role;
};

// `components` floats per element; the accessor's type must have that many components.
// Integer components convert per the glTF spec (normalized: to [0, 1] or [-1, 1]; else the
// integer's value), which also covers KHR_mesh_quantization.
std::vector<float> readGltfFloats(const GltfContext& ctx, int accessor, int components,
                                  const AccessorUse& use);

// A VEC2, VEC3 or VEC4 accessor as readGltfFloats reads it, as Vec2s, Vec3s or Vec4s (V is
// one of them): packed floats are copied straight in, with no float array between.
template <class V>
std::vector<V> readGltfVectors(const GltfContext& ctx, int accessor, const AccessorUse& use);

// A SCALAR accessor of unsigned bytes, shorts or ints.
std::vector<uint32_t> readGltfIndices(const GltfContext& ctx, int accessor, const AccessorUse& use);

// The bytes of bufferView `view` (an embedded image), checked against its buffer.
std::vector<uint8_t> readGltfBufferView(const GltfContext& ctx, int view, const std::string& element);

// Components per element of an accessor type (TINYGLTF_TYPE_VEC3: 3); 0 for none.
int gltfTypeComponents(int type);

// The accessor's element count, after checking that the accessor exists.
size_t gltfAccessorCount(const GltfContext& ctx, int accessor, const AccessorUse& use);

}  // namespace pt
