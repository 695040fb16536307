#include "render/backend/cuda/device_scene.h"

#include <algorithm>

#include "render/compile/wide_blases.h"

namespace pt::cuda {

namespace {

// Uploads `host` into a buffer of exactly its size: a smaller scene gives memory back, and an
// empty array holds none (DeviceBuffer itself only grows).
template <class T>
void uploadFitted(DeviceBuffer<T>& buffer, const T* host, size_t count, cudaStream_t stream) {
    if (buffer.bytes() != count * sizeof(T)) buffer = DeviceBuffer<T>();
    buffer.upload(host, count, stream);
}

template <class T>
void uploadFitted(DeviceBuffer<T>& buffer, const std::vector<T>& host, cudaStream_t stream) {
    uploadFitted(buffer, host.data(), host.size(), stream);
}

template <class T>
void add(std::vector<BufferBytes>& out, const char* name, const DeviceBuffer<T>& buffer) {
    out.emplace_back(name, uint64_t(buffer.bytes()));
}

}  // namespace

void DeviceScene::uploadAll(const CompiledScene& host, cudaStream_t stream) {
    const auto anyBlas = [&host](uint32_t BlasRef::*flag) {
        return std::any_of(host.blases.begin(), host.blases.end(),
                           [flag](const BlasRef& b) { return b.*flag != 0; });
    };
    uploadFitted(positions_, host.positions, stream);
    // Kernels read normals and UVs only of meshes whose BlasRef says they have them.
    if (anyBlas(&BlasRef::hasNormals))
        uploadFitted(normals_, host.normals, stream);
    else
        normals_ = {};
    if (anyBlas(&BlasRef::hasUvs))
        uploadFitted(uvs_, host.uvs, stream);
    else
        uvs_ = {};
    uploadFitted(tangents_, host.tangents, stream);
    uploadFitted(triangles_, host.triangles, stream);
    uploadFitted(spheres_, host.spheres, stream);
    uploadFitted(triangleSlots_, host.triangleSlots, stream);
    uploadFitted(sphereSlots_, host.sphereSlots, stream);
    uploadFitted(textures_, host.textures, stream);
    uploadFitted(texels8_, host.texels8, stream);
    uploadFitted(texelsF_, host.texelsF, stream);

    // Each BLAS region holds its CPU build; room for an LBVH comes with its first GPU rebuild
    // (reserveLbvhNodes), parent links with its first refit (prepareRefit).
    hostBlases_ = host.blases;
    nodeCapacity_.assign(hostBlases_.size(), 0);
    parentsReady_.assign(hostBlases_.size(), false);
    for (size_t i = 0; i < hostBlases_.size(); ++i) nodeCapacity_[i] = host.blases[i].nodeCount;
    // A deferred BLAS (CompiledScene::deferredBlases) is about to be built here: its region has
    // room for the LBVH from the start, so that no build moves every region once more.
    for (const DeferredBlas& deferred : host.deferredBlases)
        nodeCapacity_[deferred.blas] = lbvhNodeCount(host.blases[deferred.blas].primitiveCount);
    uint32_t nodeOffset = 0;
    for (size_t i = 0; i < hostBlases_.size(); ++i) {
        hostBlases_[i].nodeOffset = nodeOffset;
        nodeOffset += nodeCapacity_[i];
    }
    blasNodes_ = {};
    blasParents_ = {};
    blasNodes_.resize(nodeOffset);
    for (size_t i = 0; i < hostBlases_.size(); ++i) {
        blasNodes_.uploadAt(hostBlases_[i].nodeOffset, host.blasNodes.data() + host.blases[i].nodeOffset,
                            host.blases[i].nodeCount, stream);
    }
    // Primitive index lists already have one entry per primitive, as an LBVH needs.
    uploadFitted(blasPrimIndices_, host.blasPrimIndices, stream);
    uploadFitted(blases_, hostBlases_, stream);

    clearCompressed();  // they come behind the first frame (expectCompressed)
    uploadMaterials(host, stream);
    uploadInstances(host, stream);
    uploadLights(host, stream);
}

void DeviceScene::clearCompressed() {
    blasCompressedNodes_ = {};
    blasCompressedPrims_ = {};
    blasCompressedTriangles_ = {};
    blasCompressedRoots_ = {};
    compressedSources_ = {};
    compressedRoots_.clear();
    compressedCounts_.clear();
    compressedPrimRanges_.clear();
}

void DeviceScene::expectCompressed(cudaStream_t stream) {
    clearCompressed();
    compressedRoots_.assign(hostBlases_.size(), kNoCompressedRoot);
    compressedCounts_.assign(hostBlases_.size(), 0);
    compressedPrimRanges_.assign(hostBlases_.size(), {0, 0});
    blasCompressedRoots_.upload(compressedRoots_, stream);
}

void DeviceScene::requantizeCompressed(uint32_t i, cudaStream_t stream) {
    if (!hasCompressedForm(i)) return;
    const uint32_t first = compressedRoots_[i];
    requantizeCompressedNodes(blasCompressedNodes_.data() + first, compressedCounts_[i], blasNodes(i),
                              compressedSources_.data() + size_t(first) * CompressedWideNode::kWidth, stream);
    const auto [firstPrim, endPrim] = compressedPrimRanges_[i];
    gatherLeafTriangles(blasCompressedTriangles_.data() + firstPrim, blasCompressedPrims_.data() + firstPrim,
                        endPrim - firstPrim, triangles_.data(), positions_.data(), hostBlases_[i], stream);
}

void DeviceScene::dropCompressed(uint32_t i, cudaStream_t stream) {
    if (!hasCompressedForm(i)) return;
    compressedRoots_[i] = kNoCompressedRoot;
    blasCompressedRoots_.uploadAt(i, &compressedRoots_[i], 1, stream);
}

bool DeviceScene::appendCompressed(CompressedWideBvh forms, const std::vector<CompressedRange>& ranges,
                                   cudaStream_t stream) {
    if (compressedRoots_.empty() || ranges.empty()) return false;
    const uint32_t firstNode = uint32_t(blasCompressedNodes_.size());
    const uint32_t firstPrim = uint32_t(blasCompressedPrims_.size());
    const uint32_t entries = uint32_t(forms.primIndices.size());
    if (uint64_t(firstPrim) + entries >= kCompressedPrimitiveLimit) return false;
    // Appended, not in place: a BLAS's old range (one node, where it was deferred) stays unused
    // until the next upload, and no other BLAS moves.
    rebaseCompressedNodes(forms, firstNode, firstPrim);
    blasCompressedNodes_.append(forms.nodes.data(), forms.nodes.size(), stream);
    blasCompressedPrims_.append(forms.primIndices.data(), entries, stream);
    compressedSources_.append(forms.sourceNodes.data(), forms.sourceNodes.size(), stream);
    blasCompressedTriangles_.growKeeping(size_t(firstPrim) + entries, stream);
    for (const CompressedRange& r : ranges) {
        PT_CHECK(r.blas < compressedRoots_.size());
        compressedRoots_[r.blas] = firstNode + r.firstNode;
        compressedCounts_[r.blas] = r.nodeCount;
        compressedPrimRanges_[r.blas] = {firstPrim + r.firstPrim, firstPrim + r.firstPrim + r.primCount};
        gatherLeafTriangles(blasCompressedTriangles_.data() + firstPrim + r.firstPrim,
                            blasCompressedPrims_.data() + firstPrim + r.firstPrim, r.primCount,
                            triangles_.data(), positions_.data(), hostBlases_[r.blas], stream);
    }
    blasCompressedRoots_.uploadAt(0, compressedRoots_.data(), compressedRoots_.size(), stream);
    return true;
}

void DeviceScene::uploadMaterials(const CompiledScene& host, cudaStream_t stream) {
    materials_.upload(host.materials, stream);
}

void DeviceScene::uploadMaterial(const CompiledScene& host, uint32_t material, cudaStream_t stream) {
    materials_.uploadAt(material, host.materials.data() + material, 1, stream);
}

void DeviceScene::uploadLights(const CompiledScene& host, cudaStream_t stream, bool environment) {
    uploadFitted(emitters_, host.emitters.emitters, stream);
    uploadFitted(emitterAlias_, host.emitters.alias, stream);
    uploadFitted(punctualLights_, host.punctualLights, stream);
    if (!environment) return;
    uploadFitted(envPdf_, host.environmentDistribution.pdf, stream);
    uploadFitted(envMarginalCdf_, host.environmentDistribution.marginalCdf, stream);
    uploadFitted(envConditionalCdf_, host.environmentDistribution.conditionalCdf, stream);
}

void DeviceScene::uploadInstances(const CompiledScene& host, cudaStream_t stream) {
    instances_.upload(host.instances, stream);
    instanceMaterials_.upload(host.instanceMaterials, stream);
    uploadFitted(mergedTriangles_, host.mergedTriangles, stream);  // indices follow the instance list
}

void DeviceScene::uploadPositions(const CompiledScene& host, uint32_t first, uint32_t count,
                                  cudaStream_t stream) {
    positions_.uploadAt(first, host.positions.data() + first, count, stream);
}

void DeviceScene::uploadNormals(const CompiledScene& host, uint32_t first, uint32_t count,
                                cudaStream_t stream) {
    if (normals_.size() != 0) normals_.uploadAt(first, host.normals.data() + first, count, stream);
}

void DeviceScene::uploadTangents(const CompiledScene& host, uint32_t first, uint32_t count,
                                 cudaStream_t stream) {
    if (tangents_.size() != 0) tangents_.uploadAt(first, host.tangents.data() + first, count, stream);
}

DeviceScene::VertexArrays DeviceScene::vertices(uint32_t first) const {
    PT_CHECK(first <= positions_.size());
    VertexArrays arrays;
    arrays.positions = positions_.data() + first;
    if (normals_.size() != 0) arrays.normals = normals_.data() + first;
    if (tangents_.size() != 0) arrays.tangents = tangents_.data() + first;
    return arrays;
}

void DeviceScene::uploadSpheres(const CompiledScene& host, uint32_t blas, cudaStream_t stream) {
    const BlasRef& b = hostBlases_[blas];
    spheres_.uploadAt(b.primitiveOffset, host.spheres.data() + b.primitiveOffset, b.primitiveCount, stream);
}

void DeviceScene::prepareRefit(uint32_t i, cudaStream_t stream) {
    if (parentsReady_[i]) return;
    if (blasParents_.size() != blasNodes_.size()) {  // the first refit of this scene
        blasParents_ = {};
        blasParents_.resize(blasNodes_.size());
        std::fill(parentsReady_.begin(), parentsReady_.end(), false);
    }
    computeParents(blasNodes(i), hostBlases_[i].nodeCount, blasParents(i), stream);
    parentsReady_[i] = true;
}

void DeviceScene::reserveLbvhNodes(uint32_t i, cudaStream_t stream) {
    const uint32_t needed = lbvhNodeCount(hostBlases_[i].primitiveCount);
    if (nodeCapacity_[i] < needed) resizeBlasRegion(i, needed, hostBlases_[i].nodeCount, stream);
}

void DeviceScene::resizeBlasRegion(uint32_t i, uint32_t capacity, uint32_t keep, cudaStream_t stream) {
    // A new layout with BLAS i's region resized; every region moves to its new offset. Child
    // indices and parent links are relative to their region, so they move as they are.
    std::vector<uint32_t> offsets(hostBlases_.size());
    uint32_t total = 0;
    for (size_t b = 0; b < hostBlases_.size(); ++b) {
        offsets[b] = total;
        total += b == i ? capacity : nodeCapacity_[b];
    }
    DeviceBuffer<BvhNode> nodes(total);
    DeviceBuffer<uint32_t> parents(blasParents_.size() != 0 ? total : 0);
    for (size_t b = 0; b < hostBlases_.size(); ++b) {
        const size_t count = b == i ? std::min(keep, capacity) : hostBlases_[b].nodeCount;
        const size_t from = hostBlases_[b].nodeOffset;
        if (count == 0) continue;
        PT_CUDA_CHECK(cudaMemcpyAsync(nodes.data() + offsets[b], blasNodes_.data() + from,
                                      count * sizeof(BvhNode), cudaMemcpyDeviceToDevice, stream));
        if (parents.size() != 0 && parentsReady_[b]) {
            PT_CUDA_CHECK(cudaMemcpyAsync(parents.data() + offsets[b], blasParents_.data() + from,
                                          count * sizeof(uint32_t), cudaMemcpyDeviceToDevice, stream));
        }
    }
    // The old buffers are freed once the copies have read them.
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    blasNodes_ = std::move(nodes);
    blasParents_ = std::move(parents);
    for (size_t b = 0; b < hostBlases_.size(); ++b) hostBlases_[b].nodeOffset = offsets[b];
    nodeCapacity_[i] = capacity;
    blases_.upload(hostBlases_, stream);
}

void DeviceScene::setBlasNodeCount(uint32_t i, uint32_t nodeCount, cudaStream_t stream) {
    hostBlases_[i].nodeCount = nodeCount;
    blases_.uploadAt(i, &hostBlases_[i], 1, stream);
    parentsReady_[i] = false;
}

void DeviceScene::uploadBlasTree(uint32_t i, const std::vector<BvhNode>& nodes,
                                 const std::vector<uint32_t>& primIndices, cudaStream_t stream) {
    const BlasRef& b = hostBlases_[i];
    PT_CHECK(primIndices.size() == b.primitiveCount && !nodes.empty());
    if (nodes.size() != nodeCapacity_[i]) {
        // The region fitted to the tree (a GPU build reserved 2n - 1 nodes; a SAH tree of 4
        // primitives a leaf holds about n), without copying what the tree replaces.
        resizeBlasRegion(i, uint32_t(nodes.size()), 0, stream);
    }
    blasNodes_.uploadAt(b.nodeOffset, nodes.data(), nodes.size(), stream);
    blasPrimIndices_.uploadAt(b.primIndexOffset, primIndices.data(), primIndices.size(), stream);
    setBlasNodeCount(i, uint32_t(nodes.size()), stream);
}

void DeviceScene::buildTlas(LbvhBuilder& lbvh, DeviceBuffer<Aabb>& boxes, cudaStream_t stream) {
    const uint32_t count = instanceCount();
    if (skipsTlasForOneInstance() && count == 1) {
        tlasNodes_ = {};
        const uint32_t only = 0;
        uploadFitted(tlasInstanceIndices_, &only, 1, stream);
        return;
    }
    tlasNodes_.resize(lbvhNodeCount(count));
    tlasInstanceIndices_.resize(count);
    boxes.resize(count);
    computeInstanceBoxes(instances_.data(), count, blases_.data(), blasNodes_.data(), boxes.data(), stream);
    lbvh.build(boxes.data(), count, tlasNodes_.data(), tlasInstanceIndices_.data(), stream);
}

void DeviceScene::uploadTlas(const CompiledScene& host, cudaStream_t stream) {
    uploadFitted(tlasNodes_, host.tlasNodes, stream);
    uploadFitted(tlasInstanceIndices_, host.tlasInstanceIndices, stream);
}

RenderScene DeviceScene::view(const CompiledScene& host) const {
    RenderScene s = host.view();  // scalars: counts of lights, environment, camera, settings
#define PT_SCENE_ARRAY(Type, name, label) s.name = name##_.span();
#include "render/kernel/scene_arrays.h"
    return s;
}

std::vector<BufferBytes> DeviceScene::buffers() const {
    std::vector<BufferBytes> out;
#define PT_SCENE_ARRAY(Type, name, label) add(out, label, name##_);
#include "render/kernel/scene_arrays.h"
    add(out, "BLAS parents (refit)", blasParents_);
    add(out, "BLAS compressed sources (refit)", compressedSources_);
    return out;
}

uint64_t DeviceScene::bytes() const {
    uint64_t total = 0;
    for (const BufferBytes& b : buffers()) total += b.second;
    return total;
}

}  // namespace pt::cuda
