#include "assets/gltf/gltf_accessors.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "assets/gltf/gltf_meshopt.h"
#include "render/util/large_array.h"

namespace pt {
namespace {

// Accessors without a bufferView allocate count * components values from nothing; a real
// one (sparse morph data) is far below this.
constexpr size_t kMaxZeroFilledElements = size_t(1) << 26;

size_t componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

}  // namespace

int gltfTypeComponents(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

namespace {

// Elements of one accessor (or of one half of its sparse block) as laid out in memory.
struct Layout {
    const uint8_t* data = nullptr;  // first element; nullptr: all zeros
    size_t stride = 0, count = 0;
    int componentType = 0, components = 0;
    bool normalized = false;
};

std::string accessorName(const AccessorUse& use, int accessor) {
    return use.role + " accessor " + std::to_string(accessor);
}

// Bytes [offset, offset + stride * (count - 1) + elementBytes) of bufferView `viewIndex`,
// checked against the view and the view against its buffer's loaded bytes.
const uint8_t* viewRange(const GltfContext& ctx, int viewIndex, size_t offset, size_t stride, size_t count,
                         size_t elementBytes, const AccessorUse& use, const std::string& what) {
    if (elementBytes == 0 || stride == 0) ctx.fail(use.element, what + " is empty");
    const auto& model = ctx.model();
    const auto& view =
        gltfElement(ctx, model.bufferViews, viewIndex, use.element, (what + " bufferView").c_str());
    const uint8_t* viewData = nullptr;
    size_t viewBytes = view.byteLength;
    if (const std::vector<uint8_t>* decoded = meshoptView(ctx, viewIndex)) {
        viewData = decoded->data();  // its bytes as decoded; the fallback buffer may hold none
        viewBytes = std::min(decoded->size(), view.byteLength);
    } else {
        gltfElement(ctx, model.buffers, view.buffer, use.element,
                    ("bufferView " + std::to_string(viewIndex) + " buffer").c_str());
        const Span<const uint8_t> buffer = gltfBufferBytes(ctx.doc, view.buffer);
        const size_t bufferBytes = buffer.count;
        if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset) {
            ctx.fail(use.element, "bufferView " + std::to_string(viewIndex) +
                                      " runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                                      std::to_string(bufferBytes) + " bytes)");
        }
        viewData = buffer.data + view.byteOffset;
    }
    const size_t available = offset <= viewBytes ? viewBytes - offset : 0;
    if (offset > viewBytes || elementBytes > available || count - 1 > (available - elementBytes) / stride) {
        ctx.fail(use.element, what + " reads past the end of bufferView " + std::to_string(viewIndex) + " (" +
                                  std::to_string(count) + " elements of " + std::to_string(elementBytes) +
                                  " bytes, stride " + std::to_string(stride) + ", from byte " +
                                  std::to_string(offset) + " of " + std::to_string(viewBytes) + ")");
    }
    return viewData + offset;
}

Layout layoutOf(const GltfContext& ctx, int index, const AccessorUse& use) {
    const std::string name = accessorName(use, index);
    const auto& acc =
        gltfElement(ctx, ctx.model().accessors, index, use.element, (use.role + " accessor").c_str());
    Layout layout;
    layout.componentType = acc.componentType;
    layout.components = gltfTypeComponents(acc.type);
    layout.normalized = acc.normalized;
    layout.count = acc.count;
    const size_t elementBytes = componentBytes(acc.componentType) * size_t(layout.components);
    if (elementBytes == 0 || acc.count == 0) {
        ctx.fail(use.element, name + " has an invalid componentType, type or count");
    }
    if (acc.bufferView < 0) {
        if (acc.count > kMaxZeroFilledElements) {
            ctx.fail(use.element, name + " has no bufferView and a count of " + std::to_string(acc.count) +
                                      ", too many to zero-fill");
        }
        return layout;
    }
    const auto& view = gltfElement(ctx, ctx.model().bufferViews, acc.bufferView, use.element,
                                   (name + " bufferView").c_str());
    layout.stride = view.byteStride != 0 ? view.byteStride : elementBytes;
    if (layout.stride < elementBytes) {
        ctx.fail(use.element, name + ": bufferView " + std::to_string(acc.bufferView) + " byteStride " +
                                  std::to_string(view.byteStride) + " is smaller than one element (" +
                                  std::to_string(elementBytes) + " bytes)");
    }
    layout.data =
        viewRange(ctx, acc.bufferView, acc.byteOffset, layout.stride, acc.count, elementBytes, use, name);
    return layout;
}

template <class T>
T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));  // glTF data need not be aligned for us
    return v;
}

float componentAsFloat(const uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const float v = load<int8_t>(p);
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const float v = load<uint8_t>(p);
            return normalized ? v / 255.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const float v = load<int16_t>(p);
            return normalized ? std::max(v / 32767.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const float v = load<uint16_t>(p);
            return normalized ? v / 65535.0f : v;
        }
        default: return float(load<uint32_t>(p));
    }
}

uint32_t componentAsIndex(const uint8_t* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
        default: return load<uint32_t>(p);
    }
}

// Converts each component of `from` with `convert` into `out`, element i going to
// element at[i] (sparse values) or i.
template <class T, class Convert>
void copyElements(const Layout& from, std::vector<T>& out, const std::vector<uint32_t>* at, Convert convert) {
    const size_t bytes = componentBytes(from.componentType);
    for (size_t i = 0; i < from.count; ++i) {
        const size_t target = at ? (*at)[i] : i;
        for (int c = 0; c < from.components; ++c) {
            out[target * size_t(from.components) + size_t(c)] =
                convert(from.data + i * from.stride + size_t(c) * bytes);
        }
    }
}

// Sparse substitution: checked like the dense part, and every index inside the accessor.
template <class T, class Convert>
void applySparse(const GltfContext& ctx, int index, const Layout& dense, std::vector<T>& out,
                 const AccessorUse& use, Convert convert) {
    const auto& sparse = ctx.model().accessors[size_t(index)].sparse;
    if (!sparse.isSparse) return;
    const std::string name = accessorName(use, index) + " sparse";
    const size_t count = sparse.count > 0 ? size_t(sparse.count) : 0;
    const size_t indexBytes = componentBytes(sparse.indices.componentType);
    if (count == 0 || count > dense.count || indexBytes == 0 ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || sparse.indices.byteOffset < 0 ||
        sparse.values.byteOffset < 0) {
        ctx.fail(use.element, name + " has an invalid count, offset or index type");
    }
    const uint8_t* indexData = viewRange(ctx, sparse.indices.bufferView, size_t(sparse.indices.byteOffset),
                                         indexBytes, count, indexBytes, use, name + " indices");
    std::vector<uint32_t> targets(count);
    for (size_t i = 0; i < count; ++i) {
        targets[i] = componentAsIndex(indexData + i * indexBytes, sparse.indices.componentType);
        if (targets[i] >= dense.count) {
            ctx.fail(use.element, name + " index " + std::to_string(targets[i]) +
                                      " is past the accessor's count " + std::to_string(dense.count));
        }
    }
    Layout values = dense;
    values.count = count;
    values.stride = componentBytes(dense.componentType) * size_t(dense.components);
    values.data = viewRange(ctx, sparse.values.bufferView, size_t(sparse.values.byteOffset), values.stride,
                            count, values.stride, use, name + " values");
    copyElements(values, out, &targets, convert);
}

// The glTF component type whose values are T's as they stand: float, unsigned int.
template <class T>
constexpr int nativeComponentType() {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, uint32_t>, "floats and indices only");
    return std::is_same_v<T, float> ? TINYGLTF_COMPONENT_TYPE_FLOAT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Where the accessor's values stand in its buffer as packed T's of T's own type and alignment
// (a mesh's float positions, its 32-bit indices), with no sparse substitution: the first of
// them, which can be copied as they are; else nullptr.
template <class T>
const T* valuesAsTheyStand(const GltfContext& ctx, int accessor, const Layout& layout) {
    const bool asTheyStand = layout.data && !ctx.model().accessors[size_t(accessor)].sparse.isSparse &&
                             layout.componentType == nativeComponentType<T>() &&
                             layout.stride == sizeof(T) * size_t(layout.components) &&
                             reinterpret_cast<uintptr_t>(layout.data) % alignof(T) == 0;
    return asTheyStand ? reinterpret_cast<const T*>(layout.data) : nullptr;
}

template <class T, class Convert>
std::vector<T> readAll(const GltfContext& ctx, int accessor, const AccessorUse& use, Convert convert) {
    const Layout layout = layoutOf(ctx, accessor, use);
    const size_t values = layout.count * size_t(layout.components);
    std::vector<T> out;
    reserveOnHugePages(out, values);
    // Values as they stand: one copy, where converting element by element into a zeroed vector
    // wrote the memory twice (at 10M triangles a tenth of the load).
    if (const T* first = valuesAsTheyStand<T>(ctx, accessor, layout)) {
        out.assign(first, first + values);
        return out;
    }
    out.resize(values, T(0));
    if (layout.data) copyElements(layout, out, nullptr, convert);
    applySparse(ctx, accessor, layout, out, use, convert);
    return out;
}

}  // namespace

namespace {

// The accessor, checked to have `components` components per element.
const tinygltf::Accessor& floatAccessor(const GltfContext& ctx, int accessor, int components,
                                        const AccessorUse& use) {
    const auto& acc =
        gltfElement(ctx, ctx.model().accessors, accessor, use.element, (use.role + " accessor").c_str());
    if (gltfTypeComponents(acc.type) != components) {
        ctx.fail(use.element, accessorName(use, accessor) + " has " +
                                  std::to_string(gltfTypeComponents(acc.type)) +
                                  " components per element, expected " + std::to_string(components));
    }
    return acc;
}

}  // namespace

std::vector<float> readGltfFloats(const GltfContext& ctx, int accessor, int components,
                                  const AccessorUse& use) {
    const auto& acc = floatAccessor(ctx, accessor, components, use);
    if (auto decoded = ctx.decodedFloats.find(accessor); decoded != ctx.decodedFloats.end())
        return decoded->second;
    const int type = acc.componentType;
    const bool normalized = acc.normalized;
    return readAll<float>(ctx, accessor, use, [type, normalized](const uint8_t* p) {
        return componentAsFloat(p, type, normalized);
    });
}

template <class V>
std::vector<V> readGltfVectors(const GltfContext& ctx, int accessor, const AccessorUse& use) {
    constexpr int kComponents = int(sizeof(V) / sizeof(float));
    static_assert(sizeof(V) == kComponents * sizeof(float) && std::is_trivially_copyable_v<V>,
                  "V: only floats, as many as the accessor's components");
    floatAccessor(ctx, accessor, kComponents, use);
    std::vector<V> out;
    if (ctx.decodedFloats.find(accessor) == ctx.decodedFloats.end()) {
        const Layout layout = layoutOf(ctx, accessor, use);
        if (const float* first = valuesAsTheyStand<float>(ctx, accessor, layout)) {
            // Straight into the vectors: a float array's copy and its conversion were a fifth
            // of a 10M-triangle load.
            reserveOnHugePages(out, layout.count);
            out.resize(layout.count);
            std::memcpy(static_cast<void*>(out.data()), first, layout.count * sizeof(V));
            return out;
        }
    }
    const std::vector<float> values = readGltfFloats(ctx, accessor, kComponents, use);
    reserveOnHugePages(out, values.size() / kComponents);
    out.resize(values.size() / kComponents);
    std::memcpy(static_cast<void*>(out.data()), values.data(), out.size() * sizeof(V));
    return out;
}

template std::vector<Vec2> readGltfVectors<Vec2>(const GltfContext&, int, const AccessorUse&);
template std::vector<Vec3> readGltfVectors<Vec3>(const GltfContext&, int, const AccessorUse&);
template std::vector<Vec4> readGltfVectors<Vec4>(const GltfContext&, int, const AccessorUse&);

std::vector<uint32_t> readGltfIndices(const GltfContext& ctx, int accessor, const AccessorUse& use) {
    const auto& acc =
        gltfElement(ctx, ctx.model().accessors, accessor, use.element, (use.role + " accessor").c_str());
    const int type = acc.componentType;
    if (gltfTypeComponents(acc.type) != 1 ||
        (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        ctx.fail(use.element,
                 accessorName(use, accessor) + " must be a SCALAR of unsigned bytes, shorts or ints");
    }
    return readAll<uint32_t>(ctx, accessor, use,
                             [type](const uint8_t* p) { return componentAsIndex(p, type); });
}

std::vector<uint8_t> readGltfBufferView(const GltfContext& ctx, int view, const std::string& element) {
    const auto& v = gltfElement(ctx, ctx.model().bufferViews, view, element, "bufferView");
    const std::string role = "image";
    const uint8_t* data = viewRange(ctx, view, 0, v.byteLength, 1, v.byteLength, {element, role}, "image");
    return std::vector<uint8_t>(data, data + v.byteLength);
}

size_t gltfAccessorCount(const GltfContext& ctx, int accessor, const AccessorUse& use) {
    return gltfElement(ctx, ctx.model().accessors, accessor, use.element, (use.role + " accessor").c_str())
        .count;
}

}  // namespace pt
