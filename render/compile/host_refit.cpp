#include "render/compile/host_refit.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstring>

#include "render/bvh/sah_cost.h"
#include "render/compile/compile_geometry.h"
#include "render/util/check.h"

namespace pt {

namespace {

template <class T>
bool copyIfDifferent(T* stored, const std::vector<T>& incoming) {
    const size_t bytes = incoming.size() * sizeof(T);
    if (bytes == 0 || std::memcmp(stored, incoming.data(), bytes) == 0) return false;
    std::memcpy(stored, incoming.data(), bytes);
    return true;
}

}  // namespace

void refitBlasOnHost(CompiledScene& compiled, uint32_t index) {
    PT_CHECK(index < compiled.blases.size());
    const BlasRef& blas = compiled.blases[index];
    PT_CHECK(size_t(blas.nodeOffset) + blas.nodeCount <= compiled.blasNodes.size());
    BvhNode* nodes = compiled.blasNodes.data() + blas.nodeOffset;
    const uint32_t* prims = compiled.blasPrimIndices.data() + blas.primIndexOffset;
    // The leaves hold every primitive, so their boxes are the work: in parallel. The interior
    // nodes are one union of two children each, after.
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, blas.nodeCount, 1024),
                      [&](const tbb::blocked_range<uint32_t>& r) {
                          for (uint32_t i = r.begin(); i != r.end(); ++i) {
                              BvhNode& node = nodes[i];
                              if (!node.isLeaf()) continue;
                              Aabb box;
                              for (uint32_t k = 0; k < node.count; ++k)
                                  box.grow(primitiveBounds(compiled, blas, prims[node.leftOrFirst + k]));
                              node.lo = box.lo;
                              node.hi = box.hi;
                          }
                      });
    if (blas.primitiveCount == 0) return;  // the single empty root stays empty
    for (uint32_t i = blas.nodeCount; i-- > 0;) {
        BvhNode& node = nodes[i];
        if (node.isLeaf()) continue;
        const BvhNode& left = nodes[node.leftOrFirst];
        const BvhNode& right = nodes[node.leftOrFirst + 1];
        node.lo = vmin(left.lo, right.lo);
        node.hi = vmax(left.hi, right.hi);
    }
}

float blasSahCost(const CompiledScene& compiled, uint32_t index) {
    PT_CHECK(index < compiled.blases.size());
    const BlasRef& blas = compiled.blases[index];
    return blas.primitiveCount > 0 ? sahCost(compiled.blasNodes.data() + blas.nodeOffset, blas.nodeCount)
                                   : 0.0f;
}

std::optional<std::vector<uint32_t>> copyMovedMeshes(const Scene& scene, const TouchedIds& touched,
                                                     CompiledScene& compiled) {
    const uint32_t meshBlases = uint32_t(compiled.blases.size()) - (compiled.merged.active() ? 1u : 0u);
    if (scene.meshes.size() != meshBlases) return std::nullopt;
    std::vector<uint32_t> moved;
    size_t firstVertex = 0;  // flattenGeometry lays the triangle meshes' vertices out in order
    for (uint32_t i = 0; i < meshBlases; ++i) {
        const Mesh& mesh = scene.meshes[i];
        const BlasRef& blas = compiled.blases[i];
        if (mesh.kind != blas.kind || mesh.primitiveCount() != blas.primitiveCount) return std::nullopt;
        const size_t first = firstVertex,
                     count = mesh.kind == GeometryKind::Spheres ? 0 : mesh.positions.size();
        firstVertex += count;
        if (firstVertex > compiled.positions.size()) return std::nullopt;
        if (!touched.contains(i)) continue;  // the edit says it left this mesh alone
        if (mesh.kind == GeometryKind::Spheres) {
            if (copyIfDifferent(compiled.spheres.data() + blas.primitiveOffset, mesh.spheres))
                moved.push_back(i);
            continue;
        }
        // Normals and tangents change shading, not boxes: copied, not refitted.
        if (mesh.normals.size() == count) copyIfDifferent(compiled.normals.data() + first, mesh.normals);
        if (!compiled.tangents.empty() && mesh.tangents.size() == count)
            copyIfDifferent(compiled.tangents.data() + first, mesh.tangents);
        if (copyIfDifferent(compiled.positions.data() + first, mesh.positions)) moved.push_back(i);
    }
    return moved;
}

}  // namespace pt
