#include "bench_bvh.h"

#include <vector>

#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/instance_bounds.h"
#include "render/bvh/primitive_bounds.h"
#include "render/bvh/sah_cost.h"
#include "render/util/stopwatch.h"
#if PT_HAVE_CUDA
#include "render/backend/cuda/gpu_bvh.h"
#endif

namespace pt::cli {

namespace {

struct BuildInput {
    std::vector<Aabb> meshBoxes;      // the largest triangle mesh's triangles, object space
    std::vector<Aabb> instanceBoxes;  // world space
};

BuildInput buildInput(const CompiledScene& scene) {
    BuildInput in;
    const BlasRef* largest = nullptr;
    for (const BlasRef& b : scene.blases) {
        if (b.kind == GeometryKind::Triangles && (!largest || b.primitiveCount > largest->primitiveCount))
            largest = &b;
    }
    if (largest) {
        for (uint32_t p = 0; p < largest->primitiveCount; ++p) {
            const TriangleIndices t = scene.triangles[largest->primitiveOffset + p];
            in.meshBoxes.push_back(
                triangleBounds(scene.positions[t.v0], scene.positions[t.v1], scene.positions[t.v2]));
        }
    }
    for (const RenderInstance& inst : scene.instances) {
        const BlasRef& b = scene.blases[inst.blas];
        in.instanceBoxes.push_back(instanceBounds(scene.blasNodes[b.nodeOffset], inst.objectToWorld));
    }
    return in;
}

template <class Fn>
std::vector<double> timeRuns(uint32_t runs, Fn&& fn) {
    fn();  // warm-up
    std::vector<double> seconds;
    for (uint32_t r = 0; r < runs; ++r) {
        const auto start = Clock::now();
        fn();
        seconds.push_back(secondsSince(start));
    }
    return seconds;
}

void addBuildRows(BenchReport& report, const char* builder, double seconds, uint32_t tris, double sahRatio) {
    report.add({"BVH", std::string("BLAS build (") + builder + ")", std::to_string(tris) + " triangles",
                seconds * 1e3, "ms", ""});
    report.add(
        {"BVH", std::string("BLAS build rate (") + builder + ")", "", tris / seconds / 1e6, "Mtris/s", ""});
    report.add({"BVH", std::string("SAH cost vs CPU binned (") + builder + ")", "", sahRatio, "x", ""});
}

#if PT_HAVE_CUDA
// Device timings by events around `fn`, which queues work on `stream`.
template <class Fn>
std::vector<double> timeDeviceRuns(uint32_t runs, cudaStream_t stream, Fn&& fn) {
    cudaEvent_t begin, end;
    PT_CUDA_CHECK(cudaEventCreate(&begin));
    PT_CUDA_CHECK(cudaEventCreate(&end));
    fn();
    std::vector<double> seconds;
    for (uint32_t r = 0; r < runs; ++r) {
        PT_CUDA_CHECK(cudaEventRecord(begin, stream));
        fn();
        PT_CUDA_CHECK(cudaEventRecord(end, stream));
        PT_CUDA_CHECK(cudaEventSynchronize(end));
        float ms = 0.0f;
        PT_CUDA_CHECK(cudaEventElapsedTime(&ms, begin, end));
        seconds.push_back(ms * 1e-3);
    }
    cudaEventDestroy(begin);
    cudaEventDestroy(end);
    return seconds;
}

void benchGpu(const BuildInput& in, const Bvh& cpuBvh, float cpuSah, uint32_t runs, BenchReport& report) {
    using namespace pt::cuda;
    const uint32_t n = uint32_t(in.meshBoxes.size());
    cudaStream_t stream;
    PT_CUDA_CHECK(cudaStreamCreate(&stream));
    DeviceBuffer<Aabb> boxes;
    boxes.upload(in.meshBoxes, stream);
    DeviceBuffer<BvhNode> nodes(lbvhNodeCount(n));
    DeviceBuffer<uint32_t> primIndices(n), parents(lbvhNodeCount(n)), visits(lbvhNodeCount(n));
    LbvhBuilder builder;
    const double build = median(timeDeviceRuns(
        runs, stream, [&] { builder.build(boxes.data(), n, nodes.data(), primIndices.data(), stream); }));
    const float gpuSah = sahCostOnDevice(nodes.data(), lbvhNodeCount(n), stream);
    addBuildRows(report, "GPU LBVH", build, n, cpuSah > 0 ? gpuSah / cpuSah : 0.0);

    computeParents(nodes.data(), lbvhNodeCount(n), parents.data(), stream);
    const double refitLbvh = median(timeDeviceRuns(runs, stream, [&] {
        refitBvh(nodes.data(), lbvhNodeCount(n), parents.data(), primIndices.data(), boxes.data(),
                 visits.data(), stream);
    }));
    report.add({"BVH", "BLAS refit (GPU)", "LBVH", refitLbvh * 1e3, "ms", ""});
    // The CPU-built tree, as the backend uploads it, refitted on the GPU.
    DeviceBuffer<BvhNode> cpuNodes;
    DeviceBuffer<uint32_t> cpuPrims;
    cpuNodes.upload(cpuBvh.nodes, stream);
    cpuPrims.upload(cpuBvh.primIndices, stream);
    const uint32_t cpuCount = uint32_t(cpuBvh.nodes.size());
    computeParents(cpuNodes.data(), cpuCount, parents.data(), stream);
    const double refitCpu = median(timeDeviceRuns(runs, stream, [&] {
        refitBvh(cpuNodes.data(), cpuCount, parents.data(), cpuPrims.data(), boxes.data(), visits.data(),
                 stream);
    }));
    report.add({"BVH", "BLAS refit (GPU)", "CPU binned SAH tree", refitCpu * 1e3, "ms", ""});

    const uint32_t instances = uint32_t(in.instanceBoxes.size());
    DeviceBuffer<Aabb> instanceBoxes;
    instanceBoxes.upload(in.instanceBoxes, stream);
    DeviceBuffer<BvhNode> tlas(lbvhNodeCount(instances));
    DeviceBuffer<uint32_t> tlasIndices(instances);
    const double tlasBuild = median(timeDeviceRuns(runs, stream, [&] {
        builder.build(instanceBoxes.data(), instances, tlas.data(), tlasIndices.data(), stream);
    }));
    report.add({"BVH", "TLAS build (GPU LBVH)", std::to_string(instances) + " instances", tlasBuild * 1e3,
                "ms", ""});
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    cudaStreamDestroy(stream);
}
#endif

}  // namespace

void benchBvhBuilds(const CompiledScene& scene, bool gpu, uint32_t runs, BenchReport& report) {
    const BuildInput in = buildInput(scene);
    const uint32_t n = uint32_t(in.meshBoxes.size());
    Bvh cpuBvh;
    const double cpuBuild =
        median(timeRuns(runs, [&] { cpuBvh = buildBinnedSahBvh(in.meshBoxes.data(), n); }));
    const float cpuSah = sahCost(cpuBvh);
    addBuildRows(report, "CPU binned SAH", cpuBuild, n, 1.0);
    report.add({"BVH", "SAH cost (CPU binned)", "", cpuSah, "", "the baseline of the ratios"});
    const double tlasBuild = median(timeRuns(
        runs, [&] { buildBinnedSahBvh(in.instanceBoxes.data(), uint32_t(in.instanceBoxes.size())); }));
    report.add({"BVH", "TLAS build (CPU binned SAH)", std::to_string(in.instanceBoxes.size()) + " instances",
                tlasBuild * 1e3, "ms", ""});
#if PT_HAVE_CUDA
    if (gpu && n > 0) benchGpu(in, cpuBvh, cpuSah, runs, report);
#else
    (void)gpu;
#endif
}

}  // namespace pt::cli
