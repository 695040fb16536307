#pragma once
// DeviceScene: the CUDA backend's copy of a CompiledScene in device memory, and the
// RenderScene view of it that kernels read. Uploads come whole (a new scene) or in the parts
// edits touch (materials, lights, instances, one mesh's vertices). Each BLAS gets room for
// an LBVH of its primitives (2n - 1 nodes), so a GPU rebuild replaces a CPU-built BLAS in place.
#include <cuda_runtime.h>

#include <cstdint>
#include <vector>

#include "render/backend/cuda/device_buffer.h"
#include "render/scene/compile_scene.h"

namespace pt::cuda {

class DeviceScene {
public:
    void uploadAll(const CompiledScene& host, cudaStream_t stream);
    void uploadMaterials(const CompiledScene& host, cudaStream_t stream);
    void uploadLights(const CompiledScene& host, cudaStream_t stream);
    void uploadInstances(const CompiledScene& host, cudaStream_t stream);
    // Positions, normals and tangents [first, first + count) from `host` (a mesh's vertices).
    void uploadVertices(const CompiledScene& host, uint32_t first, uint32_t count, cudaStream_t stream);
    // The spheres of sphere BLAS `blas`.
    void uploadSpheres(const CompiledScene& host, uint32_t blas, cudaStream_t stream);

    // Kernels' view: device arrays, with the host's camera, settings and environment scalars.
    RenderScene view(const CompiledScene& host) const;

    uint32_t blasCount() const { return uint32_t(hostBlases_.size()); }
    const BlasRef& blas(uint32_t i) const { return hostBlases_[i]; }  // device offsets
    BvhNode* blasNodes(uint32_t i) const { return blasNodes_.data() + hostBlases_[i].nodeOffset; }
    uint32_t* blasPrimIndices(uint32_t i) const { return blasPrimIndices_.data() + hostBlases_[i].primIndexOffset; }
    uint32_t* blasParents(uint32_t i) const { return blasParents_.data() + hostBlases_[i].nodeOffset; }
    uint32_t blasNodeCapacity(uint32_t i) const { return nodeCapacity_[i]; }
    // After a GPU rebuild wrote `nodeCount` nodes into BLAS i's region.
    void setBlasNodeCount(uint32_t i, uint32_t nodeCount, cudaStream_t stream);

    // The TLAS, built on the device over instanceCount() instances.
    DeviceBuffer<BvhNode> tlasNodes;
    DeviceBuffer<uint32_t> tlasInstanceIndices;
    const RenderInstance* instances() const { return instances_.data(); }
    uint32_t instanceCount() const { return uint32_t(instances_.size()); }
    const BlasRef* deviceBlases() const { return blases_.data(); }
    const BvhNode* allBlasNodes() const { return blasNodes_.data(); }

    uint64_t bytes() const;

private:
    DeviceBuffer<Vec3> positions_, normals_;
    DeviceBuffer<Vec2> uvs_;
    DeviceBuffer<Vec4> tangents_;
    DeviceBuffer<TriangleIndices> triangles_;
    DeviceBuffer<Vec4> spheres_;
    DeviceBuffer<uint32_t> triangleSlots_, sphereSlots_;
    DeviceBuffer<BlasRef> blases_;
    DeviceBuffer<BvhNode> blasNodes_;
    DeviceBuffer<uint32_t> blasPrimIndices_, blasParents_;
    DeviceBuffer<RenderInstance> instances_;
    DeviceBuffer<uint32_t> instanceMaterials_;
    DeviceBuffer<Material> materials_;
    DeviceBuffer<TextureView> textures_;
    DeviceBuffer<uint8_t> texels8_;
    DeviceBuffer<float> texelsF_;
    DeviceBuffer<Emitter> emitters_;
    DeviceBuffer<AliasEntry> emitterAlias_;
    DeviceBuffer<PunctualLight> punctualLights_;
    DeviceBuffer<float> envPdf_, envMarginalCdf_, envConditionalCdf_;

    std::vector<BlasRef> hostBlases_;      // as on the device: offsets into the padded regions
    std::vector<uint32_t> nodeCapacity_;
};

}  // namespace pt::cuda
