#pragma once
// DeviceScene: the CUDA backend's copy of a CompiledScene in device memory, and the
// RenderScene view of it that kernels read. Uploads come whole (a new scene) or in the parts
// edits touch (materials, lights, instances, a range of one mesh's vertices).
// Buffers a scene does not use are not allocated (DESIGN.md, "Leave out what a scene does not
// need"): UVs and normals where no mesh has any (kernels read them only where BlasRef says a
// mesh has them), textures, environment tables, emitters and punctual lights where there are
// none, BLAS parents until that BLAS is first refitted, the room for an LBVH (2n - 1 nodes)
// until that BLAS is first rebuilt on the GPU, and the TLAS of a one-instance scene where the
// traversal walks a lone BLAS (skipsTlasForOneInstance()).
#include <cuda_runtime.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "render/backend/cuda/device_buffer.h"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/bvh/compressed_wide_bvh.h"
#include "render/compile/compile_scene.h"

namespace pt::cuda {

// Whether a scene of exactly one instance leaves its TLAS nodes out, the kernels then walking
// that instance's BLAS directly (tlasInstanceIndices is then {0}): the shared traversal walks a
// lone instance's BLAS without the TLAS (render/bvh/tlas_traversal.h).
constexpr bool skipsTlasForOneInstance() { return true; }

// One device allocation, by name, for `pt-render bench`'s memory table.
using BufferBytes = std::pair<std::string, uint64_t>;

class DeviceScene {
public:
    void uploadAll(const CompiledScene& host, cudaStream_t stream);
    void uploadMaterials(const CompiledScene& host, cudaStream_t stream);
    void uploadMaterial(const CompiledScene& host, uint32_t material, cudaStream_t stream);  // one, in place
    // Punctual lights and the light table; the environment's sampling tables too where
    // `environment` (they change only with the environment image or its intensity).
    void uploadLights(const CompiledScene& host, cudaStream_t stream, bool environment = true);
    void uploadInstances(const CompiledScene& host, cudaStream_t stream);
    // Vertices [first, first + count) of `host` (a changed range of one mesh). Normals are
    // skipped where the device holds none (no mesh has them).
    void uploadPositions(const CompiledScene& host, uint32_t first, uint32_t count, cudaStream_t stream);
    void uploadNormals(const CompiledScene& host, uint32_t first, uint32_t count, cudaStream_t stream);
    void uploadTangents(const CompiledScene& host, uint32_t first, uint32_t count, cudaStream_t stream);
    // Where vertices from `first` on live on the device, for kernels that write them (a GPU
    // skin); normals and tangents null where the device holds none.
    struct VertexArrays {
        Vec3* positions = nullptr;
        Vec3* normals = nullptr;
        Vec4* tangents = nullptr;
    };
    VertexArrays vertices(uint32_t first) const;
    // The spheres of sphere BLAS `blas`.
    void uploadSpheres(const CompiledScene& host, uint32_t blas, cudaStream_t stream);

    // Kernels' view: device arrays, with the host's camera, settings and environment scalars.
    // Valid until the next upload, prepareRefit, reserveLbvhNodes or buildTlas.
    RenderScene view(const CompiledScene& host) const;

    uint32_t blasCount() const { return uint32_t(hostBlases_.size()); }
    const BlasRef& blas(uint32_t i) const { return hostBlases_[i]; }  // device offsets
    BvhNode* blasNodes(uint32_t i) const { return blasNodes_.data() + hostBlases_[i].nodeOffset; }
    uint32_t* blasPrimIndices(uint32_t i) const {
        return blasPrimIndices_.data() + hostBlases_[i].primIndexOffset;
    }
    // BLAS i's parent links: valid after prepareRefit(i).
    uint32_t* blasParents(uint32_t i) const { return blasParents_.data() + hostBlases_[i].nodeOffset; }
    uint32_t blasNodeCapacity(uint32_t i) const { return nodeCapacity_[i]; }
    // Before the first refit of BLAS i: allocates the parent links (for every BLAS's region)
    // and computes BLAS i's.
    void prepareRefit(uint32_t i, cudaStream_t stream);
    // Before the first GPU rebuild of BLAS i: gives its region room for lbvhNodeCount(its
    // primitives), moving the BLASes' nodes and parents into a larger buffer where it has none.
    void reserveLbvhNodes(uint32_t i, cudaStream_t stream);
    // After a GPU rebuild wrote `nodeCount` nodes into BLAS i's region: its parent links come
    // with its next refit (prepareRefit).
    void setBlasNodeCount(uint32_t i, uint32_t nodeCount, cudaStream_t stream);
    // A host-built tree of BLAS i's primitives in place of its GPU build, its region fitted to
    // the tree.
    void uploadBlasTree(uint32_t i, const std::vector<BvhNode>& nodes,
                        const std::vector<uint32_t>& primIndices, cudaStream_t stream);

    // BLAS i's compressed 8-wide nodes (where the scene has them): requantised after a refit
    // of its binary nodes (its leaf triangles gathered again from the moved positions), or
    // dropped after a GPU rebuild (its new topology has no compressed form yet: the kernels
    // walk its binary nodes).
    bool hasCompressedForm(uint32_t i) const {
        return i < compressedRoots_.size() && compressedRoots_[i] != kNoCompressedRoot;
    }
    bool anyCompressedForm() const {
        return std::any_of(compressedRoots_.begin(), compressedRoots_.end(),
                           [](uint32_t root) { return root != kNoCompressedRoot; });
    }
    void requantizeCompressed(uint32_t i, cudaStream_t stream);
    void dropCompressed(uint32_t i, cudaStream_t stream);
    // A scene's compressed forms come after its upload, built on the host behind the first
    // frame: until then every BLAS walks its binary nodes. With the toggle on, expectCompressed
    // gives each BLAS an empty root (kNoCompressedRoot); appendCompressed then adds forms built
    // from binary trees now in their regions, after every BLAS's nodes and entries, and points
    // the BLASes of `ranges` (each a range of `forms`) at theirs, their leaf triangles gathered
    // from the current positions. It returns false, and those BLASes keep walking their binary
    // nodes, where the toggle is off or the entries would pass kCompressedPrimitiveLimit.
    struct CompressedRange {
        uint32_t blas, firstNode, nodeCount, firstPrim, primCount;
    };
    void expectCompressed(cudaStream_t stream);
    bool appendCompressed(CompressedWideBvh forms, const std::vector<CompressedRange>& ranges,
                          cudaStream_t stream);

    // The TLAS over the instances (GPU LBVH over their world boxes, `boxes` its scratch), or
    // only tlasInstanceIndices = {0} for one instance where skipsTlasForOneInstance().
    void buildTlas(LbvhBuilder& lbvh, DeviceBuffer<Aabb>& boxes, cudaStream_t stream);
    // The host's TLAS (CompiledScene::tlasNodes, binned SAH), uploaded in place of a GPU build.
    void uploadTlas(const CompiledScene& host, cudaStream_t stream);
    uint32_t instanceCount() const { return uint32_t(instances_.size()); }

    // Every buffer's allocated bytes, by name, in a fixed order (zero where not allocated).
    std::vector<BufferBytes> buffers() const;
    uint64_t bytes() const;

private:
    void clearCompressed();
    // A new layout of the BLAS node regions (and parent links) with BLAS i's holding `capacity`
    // nodes, of which it keeps its first `keep` (at most `capacity`); the others move as they
    // are.
    void resizeBlasRegion(uint32_t i, uint32_t capacity, uint32_t keep, cudaStream_t stream);

    // One buffer per scene array (render/kernel/scene_arrays.h), named as the array with a
    // trailing underscore.
#define PT_SCENE_ARRAY(Type, name, label) DeviceBuffer<Type> name##_;
#include "render/kernel/scene_arrays.h"
    DeviceBuffer<uint32_t> blasParents_;  // per BLAS region, as blasNodes_: for refits
    // Per slot of blasCompressedNodes_: its binary node (CompiledScene::compressedSourceNodes).
    DeviceBuffer<uint32_t> compressedSources_;
    std::vector<uint32_t> compressedRoots_, compressedCounts_;         // per BLAS, as on the device
    std::vector<std::pair<uint32_t, uint32_t>> compressedPrimRanges_;  // per BLAS: its leaf entries

    std::vector<BlasRef> hostBlases_;     // as on the device: offsets into the node regions
    std::vector<uint32_t> nodeCapacity_;  // nodes each BLAS's region holds
    std::vector<bool> parentsReady_;      // per BLAS: its parent links are computed
};

}  // namespace pt::cuda
