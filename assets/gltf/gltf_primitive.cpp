#include "assets/gltf/gltf_primitive.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <numeric>

#include "assets/gltf/gltf_accessors.h"
#include "assets/gltf/gltf_draco.h"
#include "assets/mesh_normals.h"
#include "render/util/first_failing.h"
#include "render/util/large_array.h"

namespace pt {
namespace {

const char* modeName(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return nullptr;
    }
}

// Triangle list from the primitive's corner sequence (glTF 2.0 section 3.7.2.1):
// strips p_i = {v_i, v_(i+1+i%2), v_(i+2-i%2)}, fans p_i = {v_(i+1), v_(i+2), v_0}.
std::vector<uint32_t> toTriangleList(const GltfContext& ctx, std::vector<uint32_t> corners, int mode,
                                     const std::string& element) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (corners.size() % 3 != 0) {
            ctx.fail(element,
                     "TRIANGLES with " + std::to_string(corners.size()) + " indices, not a multiple of 3");
        }
        return corners;
    }
    std::vector<uint32_t> triangles;
    for (size_t i = 0; i + 2 < corners.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            triangles.insert(triangles.end(), {corners[i], corners[i + 1 + i % 2], corners[i + 2 - i % 2]});
        } else {
            triangles.insert(triangles.end(), {corners[i + 1], corners[i + 2], corners[0]});
        }
    }
    return triangles;
}

[[noreturn]] void failNotFinite(const GltfContext& ctx, int accessor, size_t elementIndex, float value,
                                const std::string& element, const std::string& role) {
    ctx.fail(element, role + " accessor " + std::to_string(accessor) + " element " +
                          std::to_string(elementIndex) + " is not finite (" + std::to_string(value) + ")");
}

std::vector<float> readFiniteFloats(const GltfContext& ctx, int accessor, int components,
                                    const std::string& element, const std::string& role) {
    std::vector<float> values = readGltfFloats(ctx, accessor, components, {element, role});
    const size_t i = firstFailing(values.size(), [&](size_t k) { return !std::isfinite(values[k]); });
    if (i < values.size()) failNotFinite(ctx, accessor, i / size_t(components), values[i], element, role);
    return values;
}

// A vector's components (V: Vec2, Vec3 or Vec4, floats only).
template <class V>
std::array<float, sizeof(V) / sizeof(float)> componentsOf(const V& v) {
    std::array<float, sizeof(V) / sizeof(float)> c;
    std::memcpy(c.data(), &v, sizeof(V));
    return c;
}

template <class V>
std::vector<V> readFiniteVectors(const GltfContext& ctx, int accessor, const std::string& element,
                                 const std::string& role) {
    std::vector<V> values = readGltfVectors<V>(ctx, accessor, {element, role});
    const auto notFinite = [&](size_t k) {
        for (const float c : componentsOf(values[k])) {
            if (!std::isfinite(c)) return true;
        }
        return false;
    };
    const size_t v = firstFailing(values.size(), notFinite);
    if (v < values.size()) {
        for (const float c : componentsOf(values[v])) {
            if (!std::isfinite(c)) failNotFinite(ctx, accessor, v, c, element, role);
        }
    }
    return values;
}

int attribute(const tinygltf::Primitive& primitive, const char* name) {
    auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
}

void checkVertexCount(const GltfContext& ctx, int accessor, size_t count, size_t vertexCount,
                      const std::string& element, const std::string& role) {
    if (count != vertexCount) {
        ctx.fail(element, role + " accessor " + std::to_string(accessor) + " has " + std::to_string(count) +
                              " elements but POSITION has " + std::to_string(vertexCount));
    }
}

// A per-vertex attribute with exactly one element per position.
std::vector<float> readVertexAttribute(const GltfContext& ctx, int accessor, int components,
                                       size_t vertexCount, const std::string& element,
                                       const std::string& role) {
    std::vector<float> values = readFiniteFloats(ctx, accessor, components, element, role);
    checkVertexCount(ctx, accessor, values.size() / size_t(components), vertexCount, element, role);
    return values;
}

template <class V>
std::vector<V> readVertexVectors(const GltfContext& ctx, int accessor, size_t vertexCount,
                                 const std::string& element, const std::string& role) {
    std::vector<V> values = readFiniteVectors<V>(ctx, accessor, element, role);
    checkVertexCount(ctx, accessor, values.size(), vertexCount, element, role);
    return values;
}

// The primitive's corners: Draco's decoded ones, its indices, or (neither) 0, 1, 2, ...; each
// checked against the vertex count.
std::vector<uint32_t> readCorners(const GltfContext& ctx, const tinygltf::Primitive& primitive,
                                  std::optional<std::vector<uint32_t>> draco, size_t vertexCount,
                                  const std::string& element) {
    if (!draco && primitive.indices < 0) {
        std::vector<uint32_t> corners;
        reserveOnHugePages(corners, vertexCount);
        corners.resize(vertexCount);
        std::iota(corners.begin(), corners.end(), 0u);
        return corners;
    }
    const std::string source = draco ? std::string("Draco corner")
                                     : "indices accessor " + std::to_string(primitive.indices) + " element";
    std::vector<uint32_t> corners =
        draco ? std::move(*draco)
              : readGltfIndices(ctx, primitive.indices, {element, std::string("indices")});
    const size_t i = firstFailing(corners.size(), [&](size_t k) { return corners[k] >= vertexCount; });
    if (i < corners.size()) {
        ctx.fail(element, source + " " + std::to_string(i) + " is " + std::to_string(corners[i]) +
                              ", past the vertex count " + std::to_string(vertexCount));
    }
    return corners;
}

// TANGENT: xyz normalised, w reduced to its sign; zero tangents (some exporters write them
// for vertices without UVs) stay zero, which tells the renderer to derive a frame.
std::vector<Vec4> readTangents(const GltfContext& ctx, int accessor, size_t vertexCount,
                               const std::string& element) {
    std::vector<Vec4> tangents = readVertexVectors<Vec4>(ctx, accessor, vertexCount, element, "TANGENT");
    for (Vec4& t : tangents) {
        const Vec3 xyz{t.x, t.y, t.z};
        const float len = length(xyz);
        if (!(len > 0.0f)) {
            t = Vec4{};
            continue;
        }
        const Vec3 unitXyz = xyz / len;
        t = {unitXyz.x, unitXyz.y, unitXyz.z, t.w < 0.0f ? -1.0f : 1.0f};
    }
    return tangents;
}

// JOINTS_n / WEIGHTS_n pairs (glTF 2.0 section 3.7.3): up to two sets of four influences. A
// set needs both attributes; joint indices are whole numbers below 65536.
std::vector<JointInfluences> readInfluences(const GltfContext& ctx, const tinygltf::Primitive& primitive,
                                            size_t vertexCount, const std::string& element) {
    std::vector<JointInfluences> influences;
    for (int set = 0; set < 2; ++set) {
        const std::string joints = "JOINTS_" + std::to_string(set),
                          weights = "WEIGHTS_" + std::to_string(set);
        const int jointsAccessor = attribute(primitive, joints.c_str());
        const int weightsAccessor = attribute(primitive, weights.c_str());
        if (jointsAccessor < 0 && weightsAccessor < 0) break;
        if (jointsAccessor < 0 || weightsAccessor < 0) {
            ctx.fail(element, joints + " and " + weights + " must come together");
        }
        const std::vector<float> j =
            readVertexAttribute(ctx, jointsAccessor, 4, vertexCount, element, joints);
        const std::vector<float> w =
            readVertexAttribute(ctx, weightsAccessor, 4, vertexCount, element, weights);
        influences.resize(vertexCount);
        for (size_t v = 0; v < vertexCount; ++v) {
            for (int i = 0; i < 4; ++i) {
                const float joint = j[4 * v + size_t(i)];
                if (!(joint >= 0.0f && joint < 65536.0f) || joint != float(int(joint))) {
                    ctx.fail(element, joints + " element " + std::to_string(v) + " is not a joint index");
                }
                influences[v].joints[4 * set + i] = uint16_t(joint);
                influences[v].weights[4 * set + i] = w[4 * v + size_t(i)];
            }
        }
    }
    return influences;
}

// values[from[k]] for each k; an empty (absent) attribute stays empty.
template <class T>
std::vector<T> gather(const std::vector<T>& values, const std::vector<uint32_t>& from) {
    if (values.empty()) return {};
    std::vector<T> out(from.size());
    for (size_t k = 0; k < from.size(); ++k) out[k] = values[from[k]];
    return out;
}

// Makes new vertex k a copy of old vertex from[k], every per-vertex array alike (morph
// deltas included, so they keep following their positions); indices are the caller's.
void remapVertices(PrimitiveGeometry& g, const std::vector<uint32_t>& from) {
    g.positions = gather(g.positions, from);
    g.normals = gather(g.normals, from);
    g.uvs = gather(g.uvs, from);
    g.tangents = gather(g.tangents, from);
    g.influences = gather(g.influences, from);
    for (MorphTarget& target : g.targets) {
        target.positionDeltas = gather(target.positionDeltas, from);
        target.normalDeltas = gather(target.normalDeltas, from);
    }
}

// Flat shading needs a vertex per triangle corner.
void unshareVertices(PrimitiveGeometry& g) {
    remapVertices(g, g.indices);
    std::iota(g.indices.begin(), g.indices.end(), 0u);
}

// Whether the triangles use every vertex: marked in parallel (a 10M-triangle mesh has 30M
// corners), so the common case skips compactVertices' serial first-use pass.
bool usesEveryVertex(const PrimitiveGeometry& g) {
    const size_t vertices = g.positions.size();
    std::unique_ptr<std::atomic<uint8_t>[]> used(new std::atomic<uint8_t>[vertices]());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.indices.size(), size_t(1) << 16),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i < r.end(); ++i)
                              used[g.indices[i]].store(1, std::memory_order_relaxed);
                      });
    return firstFailing(vertices, [&](size_t v) { return used[v].load(std::memory_order_relaxed) == 0; }) ==
           vertices;
}

// Keeps only the vertices the triangles use, in first-use order: several primitives often
// index one shared vertex accessor, which would otherwise be copied whole into each. Where
// every vertex is used (one primitive over its own accessor, the common case) the arrays stay
// as they are: at 10M triangles copying them once more was a fifth of the load, most of it
// the kernel zeroing fresh pages.
void compactVertices(PrimitiveGeometry& g) {
    if (usesEveryVertex(g)) return;
    constexpr uint32_t kUnused = ~0u;
    std::vector<uint32_t> remap(g.positions.size(), kUnused);
    std::vector<uint32_t> used;
    for (const uint32_t index : g.indices) {
        if (remap[index] == kUnused) {
            remap[index] = uint32_t(used.size());
            used.push_back(index);
        }
    }
    if (used.size() == g.positions.size()) return;
    for (uint32_t& index : g.indices) index = remap[index];
    remapVertices(g, used);
}

// The primitive's morph targets (glTF 2.0 section 3.7.2.2), one element per position each.
// TANGENT deltas are dropped without a warning: tangents are not deformed, and the shading
// frame re-orthogonalizes the tangent against the deformed normal (integrator/surface_hit.h),
// which is close for the moderate bends morph targets make. NORMAL deltas of a primitive
// without NORMAL are dropped too: they would move generated normals the author never saw.
// Such a primitive's flat normals stay those of the undeformed triangles (Mesh keeps no
// record of which normals were generated, so applyMorphWeights cannot regenerate them).
std::vector<MorphTarget> readMorphTargets(const GltfContext& ctx, const tinygltf::Primitive& primitive,
                                          size_t vertexCount, bool hasNormals, const std::string& element) {
    std::vector<MorphTarget> targets(primitive.targets.size());
    for (size_t t = 0; t < targets.size(); ++t) {
        const std::string at = element + ".targets[" + std::to_string(t) + "]";
        for (const auto& [name, accessor] : primitive.targets[t]) {
            if (name == "TANGENT" || (name == "NORMAL" && !hasNormals)) continue;
            if (name != "POSITION" && name != "NORMAL") {
                ctx.warn(at, "morph target attribute " + name + " is not applied; ignored");
                continue;
            }
            std::vector<Vec3> deltas = readVertexVectors<Vec3>(ctx, accessor, vertexCount, at, name);
            (name == "POSITION" ? targets[t].positionDeltas : targets[t].normalDeltas) = std::move(deltas);
        }
        // A target without POSITION leaves the positions where they are.
        if (targets[t].positionDeltas.empty()) targets[t].positionDeltas.assign(vertexCount, Vec3(0.0f));
    }
    return targets;
}

// Normalizes the file's normals; regenerates zero ones (with one warning) or, when the file
// has none, all of them.
void finishNormals(const GltfContext& ctx, bool fromFile, PrimitiveGeometry& g, const std::string& element) {
    const size_t vertices = g.positions.size();
    if (!fromFile) {
        g.normals.assign(vertices, Vec3(0.0f, 0.0f, 1.0f));
        generateAreaWeightedNormals(g.positions, g.indices, std::vector<bool>(vertices, true), g.normals);
        return;
    }
    // Normalised in parallel (a 10M-triangle mesh has 5M normals); zero-length ones are counted
    // and left as they are, for the surrounding triangles to replace.
    const size_t zero = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, vertices, size_t(1) << 16), size_t(0),
        [&](const tbb::blocked_range<size_t>& r, size_t found) {
            for (size_t v = r.begin(); v < r.end(); ++v) {
                const float len = length(g.normals[v]);
                if (len > 0.0f)
                    g.normals[v] = g.normals[v] / len;
                else
                    ++found;
            }
            return found;
        },
        [](size_t a, size_t b) { return a + b; });
    if (zero == 0) return;
    ctx.warn(element, std::to_string(zero) +
                          " zero-length NORMAL vectors replaced by the surrounding triangles' normal");
    std::vector<bool> regenerate(vertices);
    for (size_t v = 0; v < vertices; ++v) regenerate[v] = !(length(g.normals[v]) > 0.0f);
    generateAreaWeightedNormals(g.positions, g.indices, regenerate, g.normals);
}

}  // namespace

std::optional<PrimitiveGeometry> readGltfPrimitive(const GltfContext& ctx, size_t meshIndex,
                                                   size_t primitiveIndex) {
    const auto& primitive = ctx.model().meshes[meshIndex].primitives[primitiveIndex];
    const std::string element =
        gltfPath("meshes", meshIndex) + ".primitives[" + std::to_string(primitiveIndex) + "]";
    // Draco-compressed attributes and indices are decoded first; the accessor readers then
    // return them (gltf_draco.h). No other primitive extension changes how geometry is read
    // (KHR_materials_variants maps materials; gltf_variants reads it). Any other optional one is
    // ignored, as the glTF specification asks, and the primitive is read as it stands; the
    // file-level warning names it. Only one the file requires is a reason to skip: its data is
    // not readable without it.
    const auto& required = ctx.model().extensionsRequired;
    std::optional<std::vector<uint32_t>> draco;
    try {
        draco = decodeGltfDraco(ctx, primitive, element);
    } catch (const InputError& e) {
        // Like an undecodable texture: one warning, and the rest of the file still shows. An
        // optional extension's primitive is read from its uncompressed fallback instead.
        const bool needed = std::find(required.begin(), required.end(), kDracoExtension) != required.end();
        ctx.scene.warnings.push_back(std::string(e.what()) +
                                     (needed ? "; primitive skipped" : "; read without it"));
        if (needed) return std::nullopt;
    }
    for (const auto& extension : primitive.extensions) {
        if (extension.first == kDracoExtension && (draco || gltfDracoAvailable())) continue;
        if (std::find(required.begin(), required.end(), extension.first) != required.end()) {
            ctx.warn(element,
                     "requires extension " + extension.first + ", which is not supported; primitive skipped");
            return std::nullopt;
        }
    }
    const char* mode = modeName(primitive.mode);
    if (!mode) ctx.fail(element, "mode " + std::to_string(primitive.mode) + " is not a glTF mode");
    if (primitive.mode < TINYGLTF_MODE_TRIANGLES) {
        ctx.warn(element, std::string(mode) + " primitives are not rendered; skipped");
        return std::nullopt;
    }
    const int position = attribute(primitive, "POSITION");
    if (position < 0) {
        ctx.warn(element, "has no POSITION attribute; skipped");
        return std::nullopt;
    }
    PrimitiveGeometry g;
    g.positions = readFiniteVectors<Vec3>(ctx, position, element, "POSITION");
    const size_t vertexCount = g.positions.size();
    g.indices = toTriangleList(ctx, readCorners(ctx, primitive, std::move(draco), vertexCount, element),
                               primitive.mode, element);
    if (g.indices.empty()) {
        ctx.warn(element, "has no triangles; skipped");
        return std::nullopt;
    }
    if (const int uv = attribute(primitive, "TEXCOORD_0"); uv >= 0) {
        g.uvs = readVertexVectors<Vec2>(ctx, uv, vertexCount, element, "TEXCOORD_0");
    }
    g.influences = readInfluences(ctx, primitive, vertexCount, element);
    const int normal = attribute(primitive, "NORMAL");
    g.targets = readMorphTargets(ctx, primitive, vertexCount, normal >= 0, element);
    if (normal >= 0) {
        g.normals = readVertexVectors<Vec3>(ctx, normal, vertexCount, element, "NORMAL");
        if (const int tangent = attribute(primitive, "TANGENT"); tangent >= 0) {
            g.tangents = readTangents(ctx, tangent, vertexCount, element);
        }
        compactVertices(g);
    } else {
        unshareVertices(g);
    }
    finishNormals(ctx, normal >= 0, g, element);
    return g;
}

}  // namespace pt
