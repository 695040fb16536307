#include "render/backend/cuda/device_scene.h"

#include <algorithm>

#include "render/backend/cuda/gpu_bvh.h"

namespace pt::cuda {

void DeviceScene::uploadAll(const CompiledScene& host, cudaStream_t stream) {
    positions_.upload(host.positions, stream);
    normals_.upload(host.normals, stream);
    uvs_.upload(host.uvs, stream);
    tangents_.upload(host.tangents, stream);
    triangles_.upload(host.triangles, stream);
    spheres_.upload(host.spheres, stream);
    triangleSlots_.upload(host.triangleSlots, stream);
    sphereSlots_.upload(host.sphereSlots, stream);
    textures_.upload(host.textures, stream);
    texels8_.upload(host.texels8, stream);
    texelsF_.upload(host.texelsF, stream);

    // Each BLAS region holds its CPU build now and an LBVH of the same primitives later.
    hostBlases_ = host.blases;
    nodeCapacity_.assign(hostBlases_.size(), 0);
    uint32_t nodeOffset = 0;
    for (size_t i = 0; i < hostBlases_.size(); ++i) {
        nodeCapacity_[i] = std::max(lbvhNodeCount(hostBlases_[i].primitiveCount), host.blases[i].nodeCount);
        hostBlases_[i].nodeOffset = nodeOffset;
        nodeOffset += nodeCapacity_[i];
    }
    blasNodes_.resize(nodeOffset);
    blasParents_.resize(nodeOffset);
    for (size_t i = 0; i < hostBlases_.size(); ++i) {
        blasNodes_.uploadAt(hostBlases_[i].nodeOffset, host.blasNodes.data() + host.blases[i].nodeOffset,
                            host.blases[i].nodeCount, stream);
        computeParents(blasNodes(uint32_t(i)), hostBlases_[i].nodeCount, blasParents(uint32_t(i)), stream);
    }
    // Primitive index lists already have one entry per primitive, as an LBVH needs.
    blasPrimIndices_.upload(host.blasPrimIndices, stream);
    blases_.upload(hostBlases_, stream);

    uploadMaterials(host, stream);
    uploadInstances(host, stream);
    uploadLights(host, stream);
}

void DeviceScene::uploadMaterials(const CompiledScene& host, cudaStream_t stream) {
    materials_.upload(host.materials, stream);
}

void DeviceScene::uploadLights(const CompiledScene& host, cudaStream_t stream) {
    emitters_.upload(host.emitters.emitters, stream);
    emitterAlias_.upload(host.emitters.alias, stream);
    punctualLights_.upload(host.punctualLights, stream);
    envPdf_.upload(host.environmentDistribution.pdf, stream);
    envMarginalCdf_.upload(host.environmentDistribution.marginalCdf, stream);
    envConditionalCdf_.upload(host.environmentDistribution.conditionalCdf, stream);
}

void DeviceScene::uploadInstances(const CompiledScene& host, cudaStream_t stream) {
    instances_.upload(host.instances, stream);
    instanceMaterials_.upload(host.instanceMaterials, stream);
}

void DeviceScene::uploadVertices(const CompiledScene& host, uint32_t first, uint32_t count, cudaStream_t stream) {
    positions_.uploadAt(first, host.positions.data() + first, count, stream);
    normals_.uploadAt(first, host.normals.data() + first, count, stream);
    if (!host.tangents.empty()) tangents_.uploadAt(first, host.tangents.data() + first, count, stream);
}

void DeviceScene::uploadSpheres(const CompiledScene& host, uint32_t blas, cudaStream_t stream) {
    const BlasRef& b = hostBlases_[blas];
    spheres_.uploadAt(b.primitiveOffset, host.spheres.data() + b.primitiveOffset, b.primitiveCount, stream);
}

void DeviceScene::setBlasNodeCount(uint32_t i, uint32_t nodeCount, cudaStream_t stream) {
    hostBlases_[i].nodeCount = nodeCount;
    blases_.uploadAt(i, &hostBlases_[i], 1, stream);
}

RenderScene DeviceScene::view(const CompiledScene& host) const {
    RenderScene s = host.view();  // scalars: counts of lights, environment, camera, settings
    s.positions = positions_.span();
    s.normals = normals_.span();
    s.uvs = uvs_.span();
    s.tangents = tangents_.span();
    s.triangles = triangles_.span();
    s.spheres = spheres_.span();
    s.triangleSlots = triangleSlots_.span();
    s.sphereSlots = sphereSlots_.span();
    s.blases = blases_.span();
    s.blasNodes = blasNodes_.span();
    s.blasPrimIndices = blasPrimIndices_.span();
    s.instances = instances_.span();
    s.tlasNodes = tlasNodes.span();
    s.tlasInstanceIndices = tlasInstanceIndices.span();
    s.instanceMaterials = instanceMaterials_.span();
    s.materials = materials_.span();
    s.textures = textures_.span();
    s.texels8 = texels8_.span();
    s.texelsF = texelsF_.span();
    s.emitters = emitters_.span();
    s.emitterAlias = emitterAlias_.span();
    s.punctualLights = punctualLights_.span();
    s.envPdf = envPdf_.span();
    s.envMarginalCdf = envMarginalCdf_.span();
    s.envConditionalCdf = envConditionalCdf_.span();
    return s;
}

uint64_t DeviceScene::bytes() const {
    return positions_.bytes() + normals_.bytes() + uvs_.bytes() + tangents_.bytes() + triangles_.bytes() +
           spheres_.bytes() + triangleSlots_.bytes() + sphereSlots_.bytes() + blases_.bytes() +
           blasNodes_.bytes() + blasPrimIndices_.bytes() + blasParents_.bytes() + instances_.bytes() +
           instanceMaterials_.bytes() + materials_.bytes() + textures_.bytes() + texels8_.bytes() +
           texelsF_.bytes() + emitters_.bytes() + emitterAlias_.bytes() + punctualLights_.bytes() +
           envPdf_.bytes() + envMarginalCdf_.bytes() + envConditionalCdf_.bytes() + tlasNodes.bytes() +
           tlasInstanceIndices.bytes();
}

}  // namespace pt::cuda
