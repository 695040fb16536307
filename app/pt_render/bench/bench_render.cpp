#include "pt_render/bench/bench_render.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "pt_render/bench/bench_sync.h"
#include "render/backend/toggle_states.h"
#include "render/bvh/hit.h"
#include "render/denoise/denoiser.h"  // kMinSamplesForOwnVariance
#include "render/integrator/path_state.h"
#include "render/util/stopwatch.h"

namespace pt::cli {

namespace {

struct Variant {
    std::string name;
    IntegratorToggles toggles;
    AovMask aovs = 0;  // accumulated beside the beauty
};

// The base toggles, then each toggle the backend has flipped on its own.
std::vector<Variant> variantsOf(const Backend& backend, const IntegratorToggles& base) {
    std::vector<Variant> v{{"default", base}};
    const auto flip = [&](const char* name, const std::function<void(IntegratorToggles&)>& change) {
        IntegratorToggles t = base;
        change(t);
        v.push_back({name, t});
    };
    const bool gpu = backend.name() != "cpu";
    if (gpu) {
        // Each schedule on its own, the baselines of the auto schedule's choice.
        flip("megakernel", [](IntegratorToggles& t) {
            t.autoSchedule = false;
            t.megakernel = true;
        });
        flip("wavefront", [](IntegratorToggles& t) {
            t.autoSchedule = false;
            t.megakernel = false;
        });
        flip(base.pathRegeneration ? "megakernel, regeneration off" : "megakernel, regeneration on",
             [](IntegratorToggles& t) {
                 t.autoSchedule = false;
                 t.megakernel = true;
                 t.pathRegeneration = !t.pathRegeneration;
             });
        // The wavefront's own toggles, each against the plain wavefront above.
        const auto wavefront = [&](const char* name, const std::function<void(IntegratorToggles&)>& change) {
            flip(name, [&](IntegratorToggles& t) {
                t.autoSchedule = false;
                t.megakernel = false;
                change(t);
            });
        };
        wavefront(base.streamCompaction ? "wavefront, compaction off" : "wavefront, compaction on",
                  [](IntegratorToggles& t) { t.streamCompaction = !t.streamCompaction; });
        wavefront(base.materialSort ? "wavefront, material sort off" : "wavefront, material sort on",
                  [](IntegratorToggles& t) { t.materialSort = !t.materialSort; });
        // The first-hit cache needs fixed camera rays: compare both without jitter.
        wavefront("wavefront, no jitter, first-hit cache off", [](IntegratorToggles& t) {
            t.pixelJitter = false;
            t.firstHitCache = false;
        });
        wavefront("wavefront, no jitter, first-hit cache on", [](IntegratorToggles& t) {
            t.pixelJitter = false;
            t.firstHitCache = true;
        });
    }
    if (!gpu) {
        flip(base.rayPackets ? "packets off" : "packets on",
             [](IntegratorToggles& t) { t.rayPackets = !t.rayPackets; });
    }
    flip(base.russianRoulette ? "roulette off" : "roulette on",
         [](IntegratorToggles& t) { t.russianRoulette = !t.russianRoulette; });
    flip(base.nextEventEstimation ? "NEE off" : "NEE on",
         [](IntegratorToggles& t) { t.nextEventEstimation = !t.nextEventEstimation; });
    flip(base.mergeInstances ? "merge off" : "merge on",
         [](IntegratorToggles& t) { t.mergeInstances = !t.mergeInstances; });
    flip("BVH off", [](IntegratorToggles& t) { t.bruteForce = true; });
    // What the denoiser's guides cost while they accumulate (their first kSettledGuideSamples
    // samples after every edit): the path AOVs, recorded by the generic AOV kernel on the GPU,
    // and one ray at a time on the CPU.
    v.push_back({"denoiser guides", base, kDenoiseGuideAovs});
    if (gpu) {
        for (const bool megakernel : {true, false}) {
            IntegratorToggles t = base;
            t.autoSchedule = false;
            t.megakernel = megakernel;
            v.push_back({megakernel ? "denoiser guides, megakernel" : "denoiser guides, wavefront", t,
                         kDenoiseGuideAovs});
        }
    }
    return v;
}

}  // namespace

void benchPathTracing(Backend& backend, const Scene& scene, const BenchSettings& settings,
                      BenchReport& report) {
    const double pixels = double(scene.render.width) * scene.render.height;
    for (const Variant& v : variantsOf(backend, settings.toggles)) {
        backend.setToggles(v.toggles);
        backend.setAovs(v.aovs);  // from the reset the sync makes
        try {
            syncSettled(backend, scene, SceneChanges::Settings);
        } catch (const std::invalid_argument& e) {
            report.add({"path tracing", "samples per pixel per second", v.name, 0.0, "spp/s", e.what()});
            continue;
        }
        // Warm-up: caches filled, buffers allocated, and the auto schedule's trial (timed at
        // the size of the runs' waves) over, so that no run is one of its turns.
        backend.render(settings.spp);
        for (int i = 0; i < 8 && backend.stats().schedule == "measuring"; ++i) backend.render(settings.spp);
        std::vector<double> seconds, rayRates;
        for (uint32_t r = 0; r < settings.runs; ++r) {
            backend.resetAccumulation();
            if (v.toggles.firstHitCache) backend.render(1);  // the cache is made by the first pass
            const BackendStats before = backend.stats();
            const auto start = Clock::now();
            backend.render(settings.spp);
            const double s = secondsSince(start);
            seconds.push_back(s);
            rayRates.push_back(double(backend.stats().rays - before.rays) / s / 1e6);
        }
        const double t = median(seconds);
        const BackendStats ran = backend.stats();
        std::string note;
        if (!ran.kernelVariant.empty()) note += "kernel variant " + ran.kernelVariant + "; ";
        if (v.toggles.autoSchedule && !ran.schedule.empty()) note += "auto schedule: " + ran.schedule + "; ";
        if (!ran.walk.empty()) note += ran.walk + " walk; ";
        for (const ToggleState& state : backend.toggleStates()) {
            // A backend without GPU scheduling has no scheduling toggles to speak of.
            const bool scheduling = toggleRow(state.id).scope == ToggleScope::GpuScheduling;
            if (state.requested && !state.active && (backend.capabilities().gpuScheduling || !scheduling)) {
                note += state.name + " inactive: " + state.note + "; ";
            }
        }
        report.add({"path tracing", "samples per pixel per second", v.name, settings.spp / t, "spp/s", note});
        report.add({"path tracing", "paths", v.name, pixels * settings.spp / t / 1e6, "Mpaths/s", ""});
        report.add({"path tracing", "rays", v.name, median(rayRates), "Mrays/s", ""});
    }
    backend.setToggles(settings.toggles);
    backend.setAovs(0);
    syncSettled(backend, scene, SceneChanges::Settings);
}

void benchWavefrontOverhead(Backend& backend, Scene scene, const BenchSettings& settings,
                            BenchReport& report) {
    if (!backend.capabilities().gpuScheduling) return;
    // What a path carries between the stages: its state, its closest hit, its shadow ray, its
    // entries in the path and shadow queues, and its finished RGB.
    const size_t bytes =
        sizeof(PathState) + sizeof(Hit) + sizeof(ShadowRay) + 3 * sizeof(uint32_t) + 3 * sizeof(float);
    report.add({"wavefront", "device memory per path", "", double(bytes), "bytes",
                "PathState " + std::to_string(sizeof(PathState)) + ", Hit " + std::to_string(sizeof(Hit)) +
                    ", ShadowRay " + std::to_string(sizeof(ShadowRay)) + ", queues 12, radiance 12"});
    scene.render.width = scene.render.height = 1;
    IntegratorToggles toggles = settings.toggles;
    toggles.autoSchedule = false;
    toggles.megakernel = false;
    backend.setToggles(toggles);
    syncSettled(backend, scene, SceneChanges::All);
    backend.render(1);  // warm-up
    std::vector<double> perBounce;
    for (uint32_t r = 0; r < 4 * settings.runs; ++r) {
        const auto start = Clock::now();
        backend.render(1);
        const double seconds = secondsSince(start);
        const size_t bounces = backend.pathsAlivePerBounce().size();
        if (bounces > 0) perBounce.push_back(seconds / double(bounces));
    }
    report.add({"wavefront", "fixed cost of a bounce", "1x1 image", median(perBounce) * 1e3, "ms",
                "extend, shade and shadow launches and the queue-size read-back, which the host waits for a "
                "bounce late"});
}

void benchDenoise(Backend& backend, const Scene& scene, const BenchSettings& settings, BenchReport& report) {
    backend.setToggles(settings.toggles);
    backend.setAovs(kDenoiseGuideAovs);  // from the reset this sync makes
    const std::string size = std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height);
    const std::string where =
        backend.capabilities().gpuScheduling ? "GPU kernels, without the copy to the host" : "CPU threads";
    // The first frames after an edit (below kMinSamplesForOwnVariance) add two passes: each
    // pixel's firefly limit and its neighbours' variance.
    for (const uint32_t spp : {1u, std::max(settings.spp, kMinSamplesForOwnVariance)}) {
        syncSettled(backend, scene, SceneChanges::Settings);
        backend.render(spp);
        std::vector<float> denoised;
        backend.readDenoised(denoised);  // warm-up: working memory allocated
        std::vector<double> seconds;
        for (uint32_t r = 0; r < std::max(settings.runs, 3u); ++r)
            seconds.push_back(backend.readDenoised(denoised));
        const bool first = spp < kMinSamplesForOwnVariance;
        report.add({"denoise", "a-trous filter (SVGF spatial), " + std::to_string(spp) + " spp", size,
                    median(seconds) * 1e3, "ms",
                    where + (first ? "; with the firefly and neighbour-variance passes" : "")});
    }
    backend.setAovs(0);
    syncSettled(backend, scene, SceneChanges::Settings);
}

void benchImageCheck(Backend& backend, Scene scene, const BenchSettings& settings, BenchReport& report) {
    if (!backend.capabilities().gpuScheduling) return;
    // Small enough for the CPU to match in seconds.
    const double scale = std::min(1.0, 160.0 / std::max(scene.render.width, scene.render.height));
    scene.render.width = std::max(1u, uint32_t(scene.render.width * scale));
    scene.render.height = std::max(1u, uint32_t(scene.render.height * scale));
    constexpr uint32_t kSpp = 16;
    std::vector<float> gpu, cpu;
    backend.setToggles(settings.toggles);
    syncSettled(backend, scene, SceneChanges::All);
    backend.render(kSpp);
    backend.readBeauty(gpu);
    std::unique_ptr<Backend> reference = createBackend("cpu");
    reference->setToggles(settings.toggles);
    reference->sync(scene, SceneChanges::All, {});
    reference->render(kSpp);
    reference->readBeauty(cpu);
    double worst = 0.0, sumDiff = 0.0, sumCpu = 0.0;
    for (size_t i = 0; i < cpu.size(); ++i) {
        if (i % 4 == 3) continue;
        worst = std::max(worst, double(std::fabs(gpu[i] - cpu[i])));
        sumDiff += std::fabs(gpu[i] - cpu[i]);
        sumCpu += std::fabs(cpu[i]);
    }
    const std::string size = std::to_string(scene.render.width) + "x" + std::to_string(scene.render.height) +
                             ", " + std::to_string(kSpp) + " spp";
    report.add({"image check", "largest deviation from the CPU", size, worst, "radiance", ""});
    report.add({"image check", "mean relative deviation from the CPU", size,
                sumCpu > 0 ? sumDiff / sumCpu : 0.0, "", ""});
}

}  // namespace pt::cli
