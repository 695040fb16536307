#include "render/compile/compile_geometry.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <numeric>
#include <stdexcept>

#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/primitive_bounds.h"
#include "render/util/first_failing.h"
#include "render/util/large_array.h"

namespace pt {

namespace {

std::string meshLabel(const Mesh& mesh, size_t index) {
    return "mesh " + std::to_string(index) + (mesh.name.empty() ? "" : " \"" + mesh.name + "\"");
}

void appendSlots(const Mesh& mesh, size_t index, std::vector<uint32_t>& slots) {
    const uint32_t count = mesh.primitiveCount();
    if (!mesh.primitiveSlots.empty() && mesh.primitiveSlots.size() != count) {
        throw std::invalid_argument(meshLabel(mesh, index) + ": " +
                                    std::to_string(mesh.primitiveSlots.size()) + " material slots for " +
                                    std::to_string(count) + " primitives");
    }
    // Without a list every primitive takes slot 0, so one check answers for all of them.
    const auto slotOf = [&](size_t p) { return mesh.primitiveSlots.empty() ? 0u : mesh.primitiveSlots[p]; };
    const size_t p = mesh.primitiveSlots.empty()
                         ? (mesh.slotCount == 0 ? 0u : count)
                         : firstFailing(count, [&](size_t q) { return slotOf(q) >= mesh.slotCount; });
    if (p < count) {
        throw std::invalid_argument(meshLabel(mesh, index) + ": primitive " + std::to_string(p) +
                                    " uses slot " + std::to_string(slotOf(p)) + " of " +
                                    std::to_string(mesh.slotCount));
    }
    if (mesh.primitiveSlots.empty()) {
        slots.resize(slots.size() + count, 0u);
    } else {
        slots.insert(slots.end(), mesh.primitiveSlots.begin(), mesh.primitiveSlots.end());
    }
}

// Which per-vertex arrays some triangle mesh of the scene has: the others are left empty, not
// filled with zeros for every vertex (at 10M triangles 120 MB of UVs and tangents no kernel
// reads: they read UVs only where BlasRef::hasUvs says a mesh has them).
struct VertexArraysUsed {
    bool uvs = false, tangents = false;
};

void appendTriangles(const Mesh& mesh, size_t index, const VertexArraysUsed& used, CompiledScene& out) {
    const uint32_t base = uint32_t(out.positions.size());
    const uint32_t vertexCount = uint32_t(mesh.positions.size());
    out.positions.insert(out.positions.end(), mesh.positions.begin(), mesh.positions.end());
    // Normals stay parallel to positions, and UVs and tangents too where some mesh has them;
    // meshes without them leave zeros, and their BlasRef says so.
    const bool hasNormals = mesh.normals.size() == vertexCount;
    const bool hasUvs = mesh.uvs.size() == vertexCount;
    if (hasNormals)
        out.normals.insert(out.normals.end(), mesh.normals.begin(), mesh.normals.end());
    else
        out.normals.resize(out.positions.size());
    if (hasUvs)
        out.uvs.insert(out.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
    else if (used.uvs)
        out.uvs.resize(out.positions.size());
    // Zero tangents (w = 0) mean "derive from the UVs".
    if (mesh.tangents.size() == vertexCount) {
        out.tangents.insert(out.tangents.end(), mesh.tangents.begin(), mesh.tangents.end());
    } else if (used.tangents) {
        out.tangents.resize(out.positions.size());
    }
    // Checked, then offset and copied, in parallel: a 10M-triangle mesh is one mesh.
    const uint32_t* corners = mesh.indices.data();
    const size_t triangles = mesh.indices.size() / 3, first = out.triangles.size();
    const size_t bad = firstFailing(triangles, [&](size_t t) {
        return corners[3 * t] >= vertexCount || corners[3 * t + 1] >= vertexCount ||
               corners[3 * t + 2] >= vertexCount;
    });
    if (bad < triangles) {
        throw std::invalid_argument(meshLabel(mesh, index) + ": triangle " + std::to_string(bad) +
                                    " indexes past its " + std::to_string(vertexCount) + " vertices");
    }
    out.triangles.resize(first + triangles);
    TriangleIndices* to = out.triangles.data() + first;
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, triangles, size_t(1) << 16), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t t = r.begin(); t < r.end(); ++t)
                to[t] = {base + corners[3 * t], base + corners[3 * t + 1], base + corners[3 * t + 2]};
        });
    BlasRef& blas = out.blases.back();
    blas.hasNormals = hasNormals ? 1u : 0u;
    blas.hasUvs = hasUvs ? 1u : 0u;
    appendSlots(mesh, index, out.triangleSlots);
}

// What a deferred BLAS holds until its caller builds it (DeferredBlas): one leaf over all
// `count` primitives, whose box is `box` (their union), and the identity index list.
Bvh singleLeafStandIn(const Aabb& box, uint32_t count) {
    Bvh bvh;
    bvh.nodes.resize(1);
    bvh.nodes[0].lo = box.lo;
    bvh.nodes[0].hi = box.hi;
    bvh.nodes[0].leftOrFirst = 0;
    bvh.nodes[0].count = count;
    bvh.primIndices.resize(count);
    tbb::parallel_for(
        tbb::blocked_range<uint32_t>(0, count, 1u << 16), [&](const tbb::blocked_range<uint32_t>& r) {
            std::iota(bvh.primIndices.begin() + r.begin(), bvh.primIndices.begin() + r.end(), r.begin());
        });
    return bvh;
}

}  // namespace

Aabb primitiveBounds(const CompiledScene& out, const BlasRef& blas, uint32_t p) {
    if (blas.kind == GeometryKind::Spheres) return sphereBounds(out.spheres[blas.primitiveOffset + p]);
    const TriangleIndices t = out.triangles[blas.primitiveOffset + p];
    return triangleBounds(out.positions[t.v0], out.positions[t.v1], out.positions[t.v2]);
}

void flattenGeometry(const Scene& scene, CompiledScene& out) {
    VertexArraysUsed used;
    size_t triangles = 0, vertices = 0, spheres = 0;
    for (const Mesh& m : scene.meshes) {
        spheres += m.kind == GeometryKind::Spheres ? m.spheres.size() : 0;
        if (m.kind != GeometryKind::Triangles || m.positions.empty()) continue;
        used.uvs |= m.uvs.size() == m.positions.size();
        used.tangents |= m.tangents.size() == m.positions.size();
        triangles += m.indices.size() / 3;
        vertices += m.positions.size();
    }
    // Each array reserved once (growing them mesh by mesh would copy them all each time), on
    // huge pages (large_array.h).
    reserveOnHugePages(out.triangles, triangles);
    reserveOnHugePages(out.triangleSlots, triangles);
    reserveOnHugePages(out.positions, vertices);
    reserveOnHugePages(out.normals, vertices);
    if (used.uvs) reserveOnHugePages(out.uvs, vertices);
    if (used.tangents) reserveOnHugePages(out.tangents, vertices);
    reserveOnHugePages(out.spheres, spheres);
    reserveOnHugePages(out.sphereSlots, spheres);
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& mesh = scene.meshes[i];
        BlasRef blas{};
        blas.kind = mesh.kind;
        blas.primitiveCount = mesh.primitiveCount();
        if (mesh.kind == GeometryKind::Spheres) {
            blas.primitiveOffset = uint32_t(out.spheres.size());
            out.blases.push_back(blas);
            out.spheres.insert(out.spheres.end(), mesh.spheres.begin(), mesh.spheres.end());
            appendSlots(mesh, i, out.sphereSlots);
            out.stats.spheres += mesh.spheres.size();
        } else {
            blas.primitiveOffset = uint32_t(out.triangles.size());
            out.blases.push_back(blas);
            appendTriangles(mesh, i, used, out);
            out.stats.meshTriangles += blas.primitiveCount;
        }
    }
    out.stats.blasCount = uint32_t(out.blases.size());
}

LargeArray<Aabb> primitiveBoundsOf(const CompiledScene& out, const BlasRef& blas) {
    // Every box is written below, in parallel (a scan of 10M triangles is one mesh): a
    // std::vector would first fill them all on this thread (a 10M-triangle mesh's 240 MB).
    LargeArray<Aabb> bounds(blas.primitiveCount);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, blas.primitiveCount, 1u << 14),
                      [&](const tbb::blocked_range<uint32_t>& r) {
                          for (uint32_t p = r.begin(); p != r.end(); ++p)
                              bounds[p] = primitiveBounds(out, blas, p);
                      });
    return bounds;
}

Aabb unionOfPrimitiveBounds(const CompiledScene& out, const BlasRef& blas) {
    using Range = tbb::blocked_range<uint32_t>;
    // A triangle's box is the union of its corners, so the union of the boxes is that of every
    // corner: grown straight from the positions, without a box or a kind test per primitive
    // (primitiveBounds per primitive was three quarters of a 10M-triangle stand-in's time).
    const bool triangles = blas.kind != GeometryKind::Spheres;
    return tbb::parallel_reduce(
        Range(0, blas.primitiveCount, 1u << 14), Aabb{},
        [&](const Range& r, Aabb acc) {
            if (!triangles) {
                for (uint32_t p = r.begin(); p != r.end(); ++p) acc.grow(primitiveBounds(out, blas, p));
                return acc;
            }
            const TriangleIndices* t = out.triangles.data() + blas.primitiveOffset;
            const Vec3* positions = out.positions.data();
            for (uint32_t p = r.begin(); p != r.end(); ++p) {
                acc.grow(positions[t[p].v0]);
                acc.grow(positions[t[p].v1]);
                acc.grow(positions[t[p].v2]);
            }
            return acc;
        },
        [](Aabb a, const Aabb& b) {
            a.grow(b);
            return a;
        });
}

void buildBlases(CompiledScene& out, const ProgressFn& progress, uint32_t deferFrom) {
    const size_t meshCount = out.blases.size();  // the meshes', then the merged BLAS
    std::vector<Bvh> bvhs(meshCount);
    // Leaves are made on every builder thread; reports go out at most every 1% of the
    // primitives, one at a time (ProgressFn need not be thread-safe).
    const uint64_t total = out.stats.meshTriangles + out.stats.spheres;
    const uint64_t step = std::max<uint64_t>(total / 100, 1);
    std::atomic<uint64_t> placed{0};
    std::mutex reportMutex;
    BvhBuildOptions options;
    options.onLeaf = [&](uint32_t count) {
        const uint64_t before = placed.fetch_add(count, std::memory_order_relaxed);
        if ((before + count) / step == before / step || !progress) return;
        std::unique_lock<std::mutex> lock(reportMutex, std::try_to_lock);
        if (lock) progress("build BVH", double(before + count) / double(total));
    };
    reportProgress(progress, "build BVH", 0.0);
    // The merged BLAS (always last where there is one) is never deferred: it is rewritten by
    // every compileInstances, on the host.
    const size_t deferrable = out.merged.active() ? meshCount - 1 : meshCount;
    std::vector<uint8_t> deferred(meshCount, 0);
    // Large meshes parallelise inside the builder; many small meshes parallelise here.
    tbb::parallel_for(size_t(0), meshCount, [&](size_t i) {
        const BlasRef& blas = out.blases[i];
        if (deferFrom > 0 && i < deferrable && blas.primitiveCount >= deferFrom) {
            bvhs[i] = singleLeafStandIn(unionOfPrimitiveBounds(out, blas), blas.primitiveCount);
            deferred[i] = 1;
            return;
        }
        const LargeArray<Aabb> bounds = primitiveBoundsOf(out, blas);
        bvhs[i] = buildBinnedSahBvh(bounds.data(), blas.primitiveCount, options);
    });
    out.deferredBlases.clear();
    for (size_t i = 0; i < meshCount; ++i) {
        if (deferred[i]) out.deferredBlases.push_back({uint32_t(i)});
    }
    // A lone BVH becomes the lists, moved (a 10M-triangle mesh's nodes are 320 MiB, which a copy
    // writes into fresh pages); several are copied into lists reserved once.
    const bool lone = meshCount == 1;
    if (!lone) {
        size_t nodes = 0, primIndices = 0;
        for (const Bvh& bvh : bvhs) nodes += bvh.nodes.size(), primIndices += bvh.primIndices.size();
        out.blasNodes.reserve(nodes);
        out.blasPrimIndices.reserve(primIndices);
    }
    for (size_t i = 0; i < meshCount; ++i) {
        BlasRef& blas = out.blases[i];
        blas.nodeOffset = uint32_t(out.blasNodes.size());
        blas.nodeCount = uint32_t(bvhs[i].nodes.size());
        blas.primIndexOffset = uint32_t(out.blasPrimIndices.size());
        if (lone) {
            out.blasNodes = std::move(bvhs[i].nodes);
            out.blasPrimIndices = std::move(bvhs[i].primIndices);
            continue;
        }
        out.blasNodes.insert(out.blasNodes.end(), bvhs[i].nodes.begin(), bvhs[i].nodes.end());
        out.blasPrimIndices.insert(out.blasPrimIndices.end(), bvhs[i].primIndices.begin(),
                                   bvhs[i].primIndices.end());
        bvhs[i] = Bvh{};  // its memory back before the next copy
    }
    out.stats.blasNodes = out.blasNodes.size();
    reportProgress(progress, "build BVH", 1.0);
}

}  // namespace pt
