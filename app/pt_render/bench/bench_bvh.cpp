#include "pt_render/bench/bench_bvh.h"

#include <string>
#include <utility>
#include <vector>

#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/instance_bounds.h"
#include "render/bvh/primitive_bounds.h"
#include "render/bvh/sah_cost.h"
#include "render/util/stopwatch.h"

namespace pt::cli {

namespace {

BvhBuildInput buildInput(const CompiledScene& scene) {
    BvhBuildInput in;
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

void addBuildRows(BenchReport& report, const char* builder, double seconds, uint32_t tris, double sahRatio) {
    report.add({"BVH", std::string("BLAS build (") + builder + ")", std::to_string(tris) + " triangles",
                seconds * 1e3, "ms", ""});
    report.add(
        {"BVH", std::string("BLAS build rate (") + builder + ")", "", tris / seconds / 1e6, "Mtris/s", ""});
    report.add({"BVH", std::string("SAH cost vs CPU binned (") + builder + ")", "", sahRatio, "x", ""});
}

void addDeviceRows(const DeviceBvhFigures& gpu, uint32_t tris, uint32_t instances, float cpuSah,
                   BenchReport& report) {
    for (const auto& [name, build] : {std::pair{"GPU LBVH", gpu.lbvh}, std::pair{"GPU PLOC", gpu.ploc},
                                      std::pair{"GPU H-PLOC", gpu.hploc}}) {
        const std::string builder = std::string(name) + (build.fellBack ? ", fell back to LBVH" : "");
        addBuildRows(report, builder.c_str(), build.seconds, tris, cpuSah > 0 ? build.sahCost / cpuSah : 0.0);
        addBuildRows(report, (builder + " + leaf collapse").c_str(), build.collapsedSeconds, tris,
                     cpuSah > 0 ? build.collapsedSahCost / cpuSah : 0.0);
    }
    report.add({"BVH", "BLAS refit (GPU)", "H-PLOC + leaf collapse", gpu.refitSeconds * 1e3, "ms", ""});
    report.add({"BVH", "BLAS refit (GPU)", "CPU binned SAH tree", gpu.refitCpuTreeSeconds * 1e3, "ms", ""});
    report.add({"BVH", "TLAS build (GPU LBVH)", std::to_string(instances) + " instances",
                gpu.tlasSeconds * 1e3, "ms", ""});
}

}  // namespace

void benchBvhBuilds(const CompiledScene& scene, Backend& backend, uint32_t runs, BenchReport& report) {
    BvhBuildInput in = buildInput(scene);
    const uint32_t n = uint32_t(in.meshBoxes.size());
    const double cpuBuild =
        median(timeRuns(runs, [&] { in.cpuTree = buildBinnedSahBvh(in.meshBoxes.data(), n); }));
    const float cpuSah = sahCost(in.cpuTree);
    addBuildRows(report, "CPU binned SAH", cpuBuild, n, 1.0);
    report.add({"BVH", "SAH cost (CPU binned)", "", cpuSah, "", "the baseline of the ratios"});
    const double tlasBuild = median(timeRuns(
        runs, [&] { buildBinnedSahBvh(in.instanceBoxes.data(), uint32_t(in.instanceBoxes.size())); }));
    report.add({"BVH", "TLAS build (CPU binned SAH)", std::to_string(in.instanceBoxes.size()) + " instances",
                tlasBuild * 1e3, "ms", ""});
    if (const std::optional<DeviceBvhFigures> gpu = backend.measureDeviceBvh(in, runs)) {
        addDeviceRows(*gpu, n, uint32_t(in.instanceBoxes.size()), cpuSah, report);
    }
}

}  // namespace pt::cli
