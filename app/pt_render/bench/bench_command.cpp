// pt-render bench: traversal, path tracing, BVH build and edit-latency figures of one backend,
// with the toggles on and off, each the median of several runs after a warm-up.
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "assets/atomic_file.h"
#include "cli/cli_options.h"
#include "cli/render_setup.h"
#include "cli/scene_input.h"
#include "cli/toggle_options.h"
#include "pt_render/bench/bench_animation.h"
#include "pt_render/bench/bench_bvh.h"
#include "pt_render/bench/bench_edits.h"
#include "pt_render/bench/bench_embree.h"
#include "pt_render/bench/bench_kernels.h"
#include "pt_render/bench/bench_rays.h"
#include "pt_render/bench/bench_render.h"
#include "pt_render/bench/bench_report.h"
#include "pt_render/bench/bench_sync.h"
#include "pt_render/commands.h"
#include "render/bvh/wide_walk_simd.h"
#include "render/util/stopwatch.h"

namespace pt::cli {

namespace {

struct BenchRequest {
    std::string scenePath, jsonPath;
    RenderSetup setup;  // --backend --size --seed --max-depth --threads --quiet
    BenchSettings settings;
};

BenchRequest parseBench(const std::vector<std::string>& args) {
    const Options o(
        args, joined(joined({"--json", "--runs", "--spp"}, renderSetupValuedFlags()), toggleValuedFlags()),
        joined(renderSetupSwitches(), toggleSwitches()));
    if (o.positional().size() != 1) throw UsageError("expected one SCENE argument");
    BenchRequest r;
    r.scenePath = o.positional()[0];
    r.setup = parseRenderSetup(o);
    r.jsonPath = o.value("--json").value_or("");
    r.settings.runs = o.positiveInt("--runs").value_or(5);
    r.settings.spp = o.positiveInt("--spp").value_or(4);
    r.settings.toggles = parseToggles(o);
    return r;
}

// The median rate of `runs` traces of the set after one that warms up; the hits of the last.
double tracedMrays(Backend& backend, const TracedRaySet& set, uint32_t runs, std::vector<Hit>& hits) {
    const std::vector<double> seconds = backend.traceRays(*set.rays, set.anyHit, runs + 1, &hits);
    return double(set.rays->size()) / median({seconds.begin() + 1, seconds.end()}) / 1e6;
}

// How many of `hits` differ from what the default layout found for `set`: whether a ray hit,
// and for closest hits where, which instance and which primitive (ties go to the lower instance,
// then primitive, on every layout). Any hit: which one a walk finds first is its own business;
// only whether.
size_t countDifferentHits(const std::vector<Hit>& hits, const TracedRaySet& set) {
    size_t differ = 0;
    for (size_t i = 0; i < hits.size() && i < set.hits.size(); ++i) {
        differ += hits[i].valid() != set.hits[i].valid() ||
                  (!set.anyHit && (hits[i].t != set.hits[i].t || hits[i].instance != set.hits[i].instance ||
                                   hits[i].primitive != set.hits[i].primitive));
    }
    return differ;
}

// Our traversal rates with the BVH as the toggles have it, with its binary form alone (the wide
// forms off, where they are on: the yardstick of issue 21's wide BVHs, measured in the same
// run) and with no BVH; the sets as traced with the first (for the baseline).
std::vector<TracedRaySet> benchRays(Backend& backend, const Scene& scene, const BenchRays& rays,
                                    const BenchSettings& settings, BenchReport& report) {
    std::vector<TracedRaySet> sets(3);
    sets[0].name = "primary", sets[0].rays = &rays.primary;
    sets[1].name = "diffuse bounce", sets[1].rays = &rays.diffuse;
    sets[2].name = "shadow (any hit)", sets[2].rays = &rays.shadow, sets[2].anyHit = true;
    // The wide form this backend walks: the CPU's 8-wide one or the GPU's compressed 8-wide one.
    const bool wide = backend.name() == "cpu" ? settings.toggles.wideBvh : settings.toggles.gpuWideBvh;
    struct Layout {
        const char* name;
        bool bruteForce, wide;
    };
    std::vector<Layout> layouts = {{"BVH on", false, wide}};
    if (wide) layouts.push_back({"binary BVH", false, false});
    layouts.push_back({"BVH off", true, wide});
    for (const Layout& layout : layouts) {
        const bool bvh = &layout == &layouts.front();
        IntegratorToggles toggles = settings.toggles;
        toggles.bruteForce = layout.bruteForce;
        if (!layout.wide) toggles.wideBvh = toggles.gpuWideBvh = false;
        // Settled, every layout walks the host's SAH trees (a mesh the GPU builds first gets its
        // SAH tree and compressed nodes behind its first frame), so the binary yardstick walks
        // the same tree as the compressed nodes.
        backend.setToggles(toggles);
        try {
            syncSettled(backend, scene, SceneChanges::Settings);
        } catch (const std::invalid_argument& e) {
            report.add({"rays", "all", layout.name, 0.0, "Mrays/s", e.what()});
            continue;
        }
        for (TracedRaySet& set : sets) {
            if (set.rays->empty()) continue;
            std::vector<Hit> hits;
            const double rate = tracedMrays(backend, set, settings.runs, hits);
            report.add(
                {"rays", set.name, layout.name, rate, "Mrays/s", std::to_string(set.rays->size()) + " rays"});
            if (bvh) set.mraysPerSecond = rate, set.hits = std::move(hits);
            if (!layout.bruteForce && !layout.wide && wide && set.mraysPerSecond > 0) {
                report.add({"rays", set.name, "wide / binary BVH", set.mraysPerSecond / rate, "x",
                            "same run; " + std::to_string(countDifferentHits(hits, set)) + " hits differ"});
            }
        }
    }
    backend.setToggles(settings.toggles);
    syncSettled(backend, scene, SceneChanges::Settings);
    return sets;
}

// The CPU's rays one at a time against its 8-ray packets (packet_traversal.h; closest and any
// hits), in the same run, where the packets are on: what they buy, and that the hits are the same.
// Returns each set's single-ray rate: the sets' own where they were traced one by one.
std::vector<double> benchPackets(Backend& backend, const Scene& scene, const std::vector<TracedRaySet>& sets,
                                 const BenchSettings& settings, BenchReport& report) {
    std::vector<double> singleRates;
    for (const TracedRaySet& set : sets) singleRates.push_back(set.mraysPerSecond);
    const std::vector<ToggleState> states = backend.toggleStates();
    const bool packets = std::any_of(states.begin(), states.end(), [](const ToggleState& s) {
        return s.id == ToggleId::RayPackets && s.active;
    });
    if (backend.name() != "cpu" || !packets) return singleRates;
    IntegratorToggles single = settings.toggles;
    single.rayPackets = false;
    backend.setToggles(single);
    syncSettled(backend, scene, SceneChanges::Settings);
    for (size_t i = 0; i < sets.size(); ++i) {
        const TracedRaySet& set = sets[i];
        if (set.rays->empty() || set.mraysPerSecond <= 0) continue;
        std::vector<Hit> hits;
        const double rate = tracedMrays(backend, set, settings.runs, hits);
        singleRates[i] = rate;
        report.add({"rays", set.name, "single rays", rate, "Mrays/s", ""});
        report.add({"rays", set.name, "8-ray packets / single rays", set.mraysPerSecond / rate, "x",
                    "same run; " + std::to_string(countDifferentHits(hits, set)) + " hits differ"});
    }
    backend.setToggles(settings.toggles);
    syncSettled(backend, scene, SceneChanges::Settings);
    return singleRates;
}

// The CPU's 8-wide walk at SSE2 against the level it runs (wide_walk_simd.h), in the same run,
// where that is AVX2: what the runtime dispatch buys, and that the hits are the same. Against
// the single-ray rates (benchPackets): SSE2 walks no packets.
void benchSimdLevels(Backend& backend, const std::vector<TracedRaySet>& sets,
                     const std::vector<double>& singleRates, const BenchSettings& settings,
                     BenchReport& report) {
    if (backend.name() != "cpu" || !settings.toggles.wideBvh || settings.toggles.bruteForce) return;
    const SimdLevel level = wideWalkSimdLevel();
    if (level == SimdLevel::Sse2) return;
    const ScopedSimdLevel sse2(SimdLevel::Sse2);
    for (size_t i = 0; i < sets.size(); ++i) {
        const TracedRaySet& set = sets[i];
        if (set.rays->empty() || set.mraysPerSecond <= 0) continue;
        std::vector<Hit> hits;
        const double rate = tracedMrays(backend, set, settings.runs, hits);
        report.add({"rays", set.name, "8-wide BVH, SSE2 walk", rate, "Mrays/s", ""});
        report.add({"rays", set.name, std::string(simdLevelName(level)) + " / SSE2 walk",
                    singleRates[i] / rate, "x",
                    "same run; " + std::to_string(countDifferentHits(hits, set)) + " hits differ"});
    }
}

}  // namespace

int runBench(const std::vector<std::string>& args) {
    const BenchRequest r = parseBench(args);
    const std::unique_ptr<tbb::global_control> threadLimit = limitThreads(r.setup);
    std::unique_ptr<Backend> backend = createBackend(r.setup.backend);
    ProgressBar bar(!r.setup.quiet);
    SceneInput input = loadSceneInput(r.scenePath, bar);
    Scene& scene = input.scene;
    applyRenderSetup(r.setup, scene);

    BenchReport report;
    backend->setToggles(r.settings.toggles);
    const SyncReport sync = backend->sync(scene, SceneChanges::All, bar.callback());
    bar.finish();
    report.add({"scene", "load", "", input.loadSeconds, "s", r.scenePath});
    report.add({"scene", "first sync (compile, BVH, upload)", "", sync.seconds, "s", sync.action});
    for (const SyncStep& step : sync.steps)
        report.add({"scene", "first sync: " + step.name, "", step.seconds, "s", ""});
    report.add({"scene", "triangles traced", "", double(backend->stats().triangles), "", ""});
    report.add({"scene", "instances", "", double(backend->stats().instances), "", ""});
    report.add({"scene", "device memory after the first sync", "",
                double(backend->deviceMemoryBytes()) / (1 << 20), "MiB", ""});
    // GPU backends: that memory by buffer, so what a scene does not use is seen not to be there.
    for (const auto& [buffer, bytes] : backend->deviceMemoryByBuffer()) {
        report.add({"memory", buffer, "after the first sync", double(bytes) / (1 << 20), "MiB",
                    bytes == 0 ? "not allocated" : ""});
    }
    // What a user waits for after opening the file: the first sample on screen. Then the work a
    // GPU backend left behind it (gpu_first_build: the SAH trees of large meshes, built on the
    // host while the first frames walk GPU-built ones), so the figures below are of the trees
    // the render settles on.
    const auto firstFrameStart = Clock::now();
    backend->render(1);
    report.add(
        {"scene", "first frame (1 spp after the first sync)", "", secondsSince(firstFrameStart), "s", ""});
    const std::optional<double> waited = backend->finishBackgroundWork();
    report.add({"scene", "SAH trees behind the first frame, landed after", "", waited.value_or(0.0), "s",
                waited ? "waited for after the first frame" : "none pending"});
    if (waited) {
        report.add({"scene", "device memory once they landed", "",
                    double(backend->deviceMemoryBytes()) / (1 << 20), "MiB",
                    "the GPU build's scratch freed, the BLAS nodes fitted to the SAH trees"});
    }
    backend->resetAccumulation();
    const auto phase = [&](const char* name) {
        if (!r.setup.quiet) std::fprintf(stderr, "bench: %s...\n", name);
    };
    // The host's own compile of the scene: ray sets are made and BVH builds timed from it.
    const CompiledScene compiled = compileRenderScene(scene);
    phase("rays");
    const BenchRays rays =
        makeBenchRays(compiled, scene.render.width, scene.render.height, scene.render.seed);
    const std::vector<TracedRaySet> traced = benchRays(*backend, scene, rays, r.settings, report);
    const std::vector<double> singleRates = benchPackets(*backend, scene, traced, r.settings, report);
    benchSimdLevels(*backend, traced, singleRates, r.settings, report);
    phase("path tracing");
    benchPathTracing(*backend, scene, r.settings, report);
    phase("BVH builds");
    benchBvhBuilds(compiled, *backend, r.settings.runs, report);
    if (!backend->capabilities().gpuScheduling) {
        phase("Embree baseline");  // the CPU's traversal and build against Embree's, same rays and triangles
        benchEmbree(compiled, traced, singleRates, r.settings.runs, report);
    }
    phase("edits");
    benchEdits(r.setup.backend, scene, r.settings, report);
    benchEditInFlight(r.setup.backend, scene, r.settings, report);
    phase("animation");
    benchAnimation(r.setup.backend, scene, r.settings, report);
    phase("denoise");
    benchDenoise(*backend, scene, r.settings, report);
    phase("image check");
    benchImageCheck(*backend, scene, r.settings, report);
    if (backend->capabilities().gpuScheduling) {
        benchWavefrontOverhead(*backend, scene, r.settings, report);
        benchKernelVariants(*backend, report);
    }
    report.add({"memory", "device memory after the benchmark", "",
                double(backend->deviceMemoryBytes()) / (1 << 20), "MiB", ""});

    std::printf("pt-render bench %s: backend %s (%s), %ux%u, depth %u, %u spp per run, median of %u runs\n",
                r.scenePath.c_str(), backend->name().c_str(), backend->deviceName().c_str(),
                scene.render.width, scene.render.height, scene.render.maxDepth, r.settings.spp,
                r.settings.runs);
    report.print(stdout);
    if (!r.jsonPath.empty()) {
        nlohmann::ordered_json j;
        j["scene"] = r.scenePath;
        j["backend"] = backend->name();
        j["device"] = backend->deviceName();
        j["width"] = scene.render.width;
        j["height"] = scene.render.height;
        j["max_depth"] = scene.render.maxDepth;
        j["runs"] = r.settings.runs;
        j["rows"] = report.json();
        writeTextAtomically(r.jsonPath, j.dump(2) + "\n");
    }
    return 0;
}

}  // namespace pt::cli
