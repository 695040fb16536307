// The CUDA backend's BVH builders timed for pt-render bench (render/backend/device_bvh_figures.h).
#include "render/backend/cuda/device_bvh_figures.h"

#include <algorithm>
#include <type_traits>

#include "render/backend/cuda/gpu_bvh.h"
#include "render/backend/cuda/stream_timer.h"

namespace pt::cuda {

namespace {

// The median of `runs` timings of `queue` on `stream`, after one untimed warm-up.
template <class Queue>
double medianDeviceSeconds(uint32_t runs, cudaStream_t stream, Queue&& queue) {
    StreamTimer timer;
    queue();
    std::vector<double> seconds;
    for (uint32_t r = 0; r < std::max(runs, 1u); ++r) seconds.push_back(timer.time(stream, queue));
    std::sort(seconds.begin(), seconds.end());
    return seconds[seconds.size() / 2];
}

// `builder`'s build of the n `boxes` into `nodes` and `primIndices`, timed alone and with the
// leaf collapse after it; the tree it leaves there is the collapsed one.
template <class Builder>
GpuBuildFigures measureBuild(Builder& builder, const Aabb* boxes, uint32_t n, BvhNode* nodes,
                             uint32_t* primIndices, uint32_t runs, cudaStream_t stream) {
    GpuBuildFigures figures;
    figures.seconds =
        medianDeviceSeconds(runs, stream, [&] { builder.build(boxes, n, nodes, primIndices, stream); });
    figures.sahCost = sahCostOnDevice(nodes, lbvhNodeCount(n), stream);
    if constexpr (!std::is_same_v<Builder, LbvhBuilder>) figures.fellBack = builder.lastBuildFellBack();
    // As the backend's rebuilds run them: built into the collapse's scratch, collapsed into place.
    BvhLeafCollapse collapse;
    const BvhLeafCollapse::BuildScratch built = collapse.buildScratch(lbvhNodeCount(n), n);
    uint32_t collapsedCount = 0;
    figures.collapsedSeconds = medianDeviceSeconds(runs, stream, [&] {
        builder.build(boxes, n, built.nodes, built.primIndices, stream);
        collapsedCount = collapse.collapseInto(built.nodes, lbvhNodeCount(n), built.primIndices, n, nodes,
                                               primIndices, stream, builder.subtreeChoices());
    });
    figures.collapsedSahCost = sahCostOnDevice(nodes, collapsedCount, stream);
    figures.collapsedNodes = collapsedCount;
    return figures;
}

}  // namespace

DeviceBvhFigures measureDeviceBvhBuilds(const BvhBuildInput& in, uint32_t runs, cudaStream_t stream) {
    DeviceBvhFigures figures;
    const uint32_t n = uint32_t(in.meshBoxes.size());
    DeviceBuffer<Aabb> boxes;
    boxes.upload(in.meshBoxes, stream);
    DeviceBuffer<BvhNode> nodes(lbvhNodeCount(n));
    DeviceBuffer<uint32_t> primIndices(std::max(n, 1u));
    const uint32_t parentCount = std::max(lbvhNodeCount(n), uint32_t(in.cpuTree.nodes.size()));
    DeviceBuffer<uint32_t> parents(parentCount), visits(parentCount);
    PlocBuilder ploc;
    HplocBuilder hploc;
    LbvhBuilder builder;
    figures.ploc = measureBuild(ploc, boxes.data(), n, nodes.data(), primIndices.data(), runs, stream);
    figures.lbvh = measureBuild(builder, boxes.data(), n, nodes.data(), primIndices.data(), runs, stream);
    // Last, so that its tree, collapsed as the backend's rebuilds leave it, is the one refitted below.
    figures.hploc = measureBuild(hploc, boxes.data(), n, nodes.data(), primIndices.data(), runs, stream);

    const uint32_t refitNodes = figures.hploc.collapsedNodes;
    computeParents(nodes.data(), refitNodes, parents.data(), stream);
    figures.refitSeconds = medianDeviceSeconds(runs, stream, [&] {
        refitBvh(nodes.data(), refitNodes, parents.data(), primIndices.data(), boxes.data(), visits.data(),
                 stream);
    });
    // The CPU-built tree, as the backend uploads it, refitted on the GPU.
    DeviceBuffer<BvhNode> cpuNodes;
    DeviceBuffer<uint32_t> cpuPrims;
    cpuNodes.upload(in.cpuTree.nodes, stream);
    cpuPrims.upload(in.cpuTree.primIndices, stream);
    const uint32_t cpuCount = uint32_t(in.cpuTree.nodes.size());
    computeParents(cpuNodes.data(), cpuCount, parents.data(), stream);
    figures.refitCpuTreeSeconds = medianDeviceSeconds(runs, stream, [&] {
        refitBvh(cpuNodes.data(), cpuCount, parents.data(), cpuPrims.data(), boxes.data(), visits.data(),
                 stream);
    });

    const uint32_t instances = uint32_t(in.instanceBoxes.size());
    DeviceBuffer<Aabb> instanceBoxes;
    instanceBoxes.upload(in.instanceBoxes, stream);
    DeviceBuffer<BvhNode> tlas(lbvhNodeCount(instances));
    DeviceBuffer<uint32_t> tlasIndices(std::max(instances, 1u));
    figures.tlasSeconds = medianDeviceSeconds(runs, stream, [&] {
        builder.build(instanceBoxes.data(), instances, tlas.data(), tlasIndices.data(), stream);
    });
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    return figures;
}

}  // namespace pt::cuda
