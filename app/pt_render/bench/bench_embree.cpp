#include "pt_render/bench/bench_embree.h"

#ifdef PT_HAVE_EMBREE
#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "render/util/stopwatch.h"
#endif

namespace pt::cli {

#ifndef PT_HAVE_EMBREE

void benchEmbree(const CompiledScene&, const std::vector<TracedRaySet>&, const std::vector<double>&, uint32_t,
                 BenchReport& report) {
    report.add({"embree", "baseline", "", 0.0, "", "left out: this build has no Embree (libembree-dev)"});
}

#else

namespace {

struct DeviceDeleter {
    void operator()(RTCDevice d) const { rtcReleaseDevice(d); }
};
struct SceneDeleter {
    void operator()(RTCScene s) const { rtcReleaseScene(s); }
};
using Device = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using Scene3 = std::unique_ptr<RTCSceneTy, SceneDeleter>;

// Embree's scenes over a compiled scene's primitives: the vertices copied once with the 4 bytes
// of padding Embree's vector loads read past the last one.
class EmbreeScene {
public:
    EmbreeScene(RTCDevice device, const CompiledScene& compiled) : device_(device) {
        vertices_.assign(compiled.positions.begin(), compiled.positions.end());
        vertices_.emplace_back(0.0f);
        top_.reset(rtcNewScene(device));
        const auto start = Clock::now();
        for (size_t i = 0; i < compiled.instances.size(); ++i) {
            const RenderInstance& instance = compiled.instances[i];
            if (!instance.tracedInWorldSpace) addInstance(compiled, instance.blas, instance.objectToWorld);
        }
        if (compiled.merged.active()) addInstance(compiled, compiled.merged.blas, Affine3{});
        rtcCommitScene(top_.get());
        buildSeconds = secondsSince(start);
        if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
            throw std::runtime_error("Embree could not build the scene");
    }
    RTCScene top() const { return top_.get(); }
    double buildSeconds = 0.0;

    // Builds an Embree scene of BLAS `blas` alone (medium quality, Embree's default).
    void buildAlone(const CompiledScene& compiled, uint32_t blas) { blasScene(compiled, blas); }

private:
    // Triangles over the shared vertices, or spheres as Embree's point spheres (centre and
    // radius, as ours).
    Scene3 blasScene(const CompiledScene& compiled, uint32_t blas) {
        const BlasRef& b = compiled.blases[blas];
        Scene3 scene(rtcNewScene(device_));
        RTCGeometry geometry;
        if (b.kind == GeometryKind::Triangles) {
            geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
            rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       vertices_.data(), 0, sizeof(Vec3), vertices_.size() - 1);
            rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                       compiled.triangles.data() + b.primitiveOffset, 0,
                                       sizeof(TriangleIndices), b.primitiveCount);
        } else {
            geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                       compiled.spheres.data() + b.primitiveOffset, 0, sizeof(Vec4),
                                       b.primitiveCount);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene.get(), geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene.get());
        return scene;
    }

    void addInstance(const CompiledScene& compiled, uint32_t blas, const Affine3& objectToWorld) {
        auto found = blasScenes_.find(blas);
        if (found == blasScenes_.end()) found = blasScenes_.emplace(blas, blasScene(compiled, blas)).first;
        RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(instance, found->second.get());
        // Affine3 is three rows of (x, y, z, translation): Embree's row-major 3x4.
        rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, &objectToWorld);
        rtcCommitGeometry(instance);
        rtcAttachGeometry(top_.get(), instance);
        rtcReleaseGeometry(instance);
    }

    RTCDevice device_;
    std::vector<Vec3> vertices_;
    std::map<uint32_t, Scene3> blasScenes_;
    Scene3 top_;
};

constexpr size_t kRayBlock = 256;  // rays a task

RTCRay embreeRay(const Ray& r) {
    RTCRay ray{};
    ray.org_x = r.origin.x, ray.org_y = r.origin.y, ray.org_z = r.origin.z;
    ray.dir_x = r.direction.x, ray.dir_y = r.direction.y, ray.dir_z = r.direction.z;
    ray.tnear = 0.0f;
    ray.tfar = r.tMax;
    ray.mask = 0xffffffffu;
    return ray;
}

// Embree's answer per ray: the closest hit's t (infinity for none), or 0/1 for occlusion.
std::vector<float> traceSingle(RTCScene scene, const std::vector<Ray>& rays, bool anyHit) {
    std::vector<float> t(rays.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayBlock),
                      [&](const tbb::blocked_range<size_t>& r) {
                          RTCIntersectContext context;
                          rtcInitIntersectContext(&context);
                          for (size_t i = r.begin(); i != r.end(); ++i) {
                              if (anyHit) {
                                  RTCRay ray = embreeRay(rays[i]);
                                  rtcOccluded1(scene, &context, &ray);
                                  t[i] = ray.tfar < 0.0f ? 1.0f : 0.0f;  // occluded: tfar = -inf
                              } else {
                                  RTCRayHit hit{};
                                  hit.ray = embreeRay(rays[i]);
                                  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                                  rtcIntersect1(scene, &context, &hit);
                                  t[i] = hit.hit.geomID != RTC_INVALID_GEOMETRY_ID ? hit.ray.tfar : kInf;
                              }
                          }
                      });
    return t;
}

// Closest hits (rtcIntersect8), or with `anyHit` occlusion (rtcOccluded8), in packets of eight
// consecutive rays (rays of neighbouring pixels in bench's sets).
std::vector<float> tracePackets(RTCScene scene, const std::vector<Ray>& rays, bool anyHit) {
    std::vector<float> t(rays.size());
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, (rays.size() + 7) / 8, kRayBlock / 8),
        [&](const tbb::blocked_range<size_t>& r) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            for (size_t p = r.begin(); p != r.end(); ++p) {
                alignas(32) int valid[8];
                alignas(32) RTCRayHit8 packet{};
                for (int k = 0; k < 8; ++k) {
                    const size_t i = std::min(p * 8 + size_t(k), rays.size() - 1);
                    valid[k] = p * 8 + size_t(k) < rays.size() ? -1 : 0;
                    const Ray& ray = rays[i];
                    packet.ray.org_x[k] = ray.origin.x, packet.ray.org_y[k] = ray.origin.y;
                    packet.ray.org_z[k] = ray.origin.z, packet.ray.dir_x[k] = ray.direction.x;
                    packet.ray.dir_y[k] = ray.direction.y, packet.ray.dir_z[k] = ray.direction.z;
                    packet.ray.tnear[k] = 0.0f, packet.ray.tfar[k] = ray.tMax;
                    packet.ray.mask[k] = 0xffffffffu;
                    packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                }
                if (anyHit) {
                    rtcOccluded8(valid, scene, &context, &packet.ray);
                } else {
                    rtcIntersect8(valid, scene, &context, &packet);
                }
                for (int k = 0; k < 8 && p * 8 + size_t(k) < rays.size(); ++k) {
                    if (anyHit) {
                        t[p * 8 + size_t(k)] = packet.ray.tfar[k] < 0.0f ? 1.0f : 0.0f;  // occluded: -inf
                    } else {
                        t[p * 8 + size_t(k)] =
                            packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID ? packet.ray.tfar[k] : kInf;
                    }
                }
            }
        });
    return t;
}

// Rays on which ours and Embree's agree: both miss, or both hit within a relative 1e-4 (two
// watertight tests of one triangle differ in rounding; a ray through an edge may take either
// side at the same t). For occlusion, the same answer.
double agreement(const TracedRaySet& set, const std::vector<float>& embree) {
    size_t agree = 0;
    for (size_t i = 0; i < embree.size() && i < set.hits.size(); ++i) {
        const bool oursHit = set.hits[i].valid();
        if (set.anyHit) {
            agree += oursHit == (embree[i] > 0.0f);
        } else if (!oursHit || embree[i] == kInf) {
            agree += !oursHit && embree[i] == kInf;
        } else {
            agree += std::fabs(set.hits[i].t - embree[i]) <= 1e-4f * std::fmax(1.0f, embree[i]);
        }
    }
    return embree.empty() ? 1.0 : double(agree) / double(embree.size());
}

template <class Trace>
double medianMrays(uint32_t runs, size_t rays, Trace&& trace) {
    return double(rays) / median(timeRuns(runs, trace)) / 1e6;
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f%%", 100.0 * share);
    return text;
}

void benchBuild(EmbreeScene& embree, const CompiledScene& compiled, uint32_t runs, BenchReport& report) {
    uint32_t largest = 0;
    for (uint32_t b = 0; b < compiled.blases.size(); ++b) {
        if (compiled.blases[b].kind == GeometryKind::Triangles &&
            compiled.blases[b].primitiveCount > compiled.blases[largest].primitiveCount)
            largest = b;
    }
    if (compiled.blases.empty() || compiled.blases[largest].kind != GeometryKind::Triangles) return;
    const std::vector<double> seconds = timeRuns(runs, [&] { embree.buildAlone(compiled, largest); });
    const uint32_t tris = compiled.blases[largest].primitiveCount;
    const double rate = tris / median(seconds) / 1e6;
    report.add({"embree", "BLAS build rate (Embree, medium quality)", std::to_string(tris) + " triangles",
                rate, "Mtris/s", "the largest mesh, as the BVH section's builds"});
    for (const BenchRow& row : report.rows()) {
        if (row.figure == "BLAS build rate (CPU binned SAH)" && rate > 0.0)
            report.add({"embree", "BLAS build rate, ours / Embree", "", row.value / rate, "x", "same run"});
    }
}

}  // namespace

void benchEmbree(const CompiledScene& compiled, const std::vector<TracedRaySet>& sets,
                 const std::vector<double>& singleRates, uint32_t runs, BenchReport& report) {
    // Embree's own threads, as many as TBB may use here (--threads).
    const std::string config =
        "threads=" + std::to_string(tbb::this_task_arena::max_concurrency()) + ",set_affinity=0";
    Device device(rtcNewDevice(config.c_str()));
    if (!device) {
        report.add({"embree", "baseline", "", 0.0, "", "left out: Embree could not start"});
        return;
    }
    EmbreeScene embree(device.get(), compiled);
    report.add({"embree", "scene build (Embree)", "", embree.buildSeconds * 1e3, "ms", ""});
    const bool packets = rtcGetDeviceProperty(device.get(), RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0;
    for (size_t i = 0; i < sets.size(); ++i) {
        const TracedRaySet& set = sets[i];
        if (set.rays->empty()) continue;
        std::vector<float> answers;
        double best = medianMrays(runs, set.rays->size(),
                                  [&] { answers = traceSingle(embree.top(), *set.rays, set.anyHit); });
        report.add({"embree", set.name, "Embree, single rays", best, "Mrays/s",
                    "hits agree with ours on " + percent(agreement(set, answers)) + " of rays"});
        if (packets) {
            const double packeted = medianMrays(
                runs, set.rays->size(), [&] { answers = tracePackets(embree.top(), *set.rays, set.anyHit); });
            report.add({"embree", set.name, "Embree, 8-ray packets", packeted, "Mrays/s",
                        "hits agree with ours on " + percent(agreement(set, answers)) + " of rays"});
            best = std::max(best, packeted);
        }
        // Ours at its best too: packets lose to single rays on many cores (0.88x on 16).
        const double ours = std::max(set.mraysPerSecond, i < singleRates.size() ? singleRates[i] : 0.0);
        report.add({"embree", set.name, "ours / Embree's best", ours / best, "x",
                    "same run; ours the faster of single rays and packets"});
    }
    benchBuild(embree, compiled, runs, report);
}

#endif

}  // namespace pt::cli
