// pt-render render: progressive offline render to EXR and/or PNG.
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "assets/atomic_file.h"
#include "assets/image_write.h"
#include "cli_options.h"
#include "commands.h"
#include "progress_bar.h"
#include "render/backend/backend.h"
#include "render/display/display_transform.h"
#include "render/util/stopwatch.h"
#include "scene_input.h"
#include "toggle_options.h"

namespace pt::cli {

namespace {

struct RenderRequest {
    std::string scenePath, exrPath, pngPath, statsPath, backend = "cpu";
    std::optional<uint32_t> spp, seed, threads, maxDepth;
    std::optional<double> seconds;
    std::optional<std::pair<uint32_t, uint32_t>> size;
    IntegratorToggles toggles;
    bool quiet = false;
};

RenderRequest parseRequest(const std::vector<std::string>& args) {
    const Options o(args,
                    joined({"-o", "--png", "--spp", "--time", "--size", "--seed", "--threads", "--backend", "--stats",
                            "--max-depth"},
                           toggleValuedFlags()),
                    joined({"--quiet"}, toggleSwitches()));
    if (o.positional().size() != 1) throw UsageError("expected one SCENE argument");
    RenderRequest r;
    r.scenePath = o.positional()[0];
    r.exrPath = o.value("-o").value_or("");
    r.pngPath = o.value("--png").value_or("");
    if (r.exrPath.empty() && r.pngPath.empty()) throw UsageError("give an output: -o OUT.exr and/or --png OUT.png");
    r.statsPath = o.value("--stats").value_or("");
    r.backend = o.value("--backend").value_or("cpu");
    r.spp = o.positiveInt("--spp");
    r.seconds = o.positiveNumber("--time");
    if (r.spp && r.seconds) throw UsageError("--spp and --time exclude each other");
    r.seed = o.nonNegativeInt("--seed");
    r.threads = o.positiveInt("--threads");
    r.maxDepth = o.nonNegativeInt("--max-depth");
    r.size = o.size("--size");
    r.quiet = o.has("--quiet");
    r.toggles = parseToggles(o);
    return r;
}

// Renders until the sample or time budget is met, in batches of about a quarter second so
// the progress bar moves; with --time no batch is planned past the budget.
void accumulate(Backend& backend, const RenderRequest& r, uint32_t targetSpp, ProgressBar& bar) {
    const auto start = Clock::now();
    double secondsPerPass = 0.0;  // unknown until the first batch
    for (;;) {
        const double elapsed = secondsSince(start);
        const uint32_t done = backend.stats().samplesPerPixel;
        if (r.seconds ? elapsed >= *r.seconds : done >= targetSpp) break;
        bar.update("render", r.seconds ? elapsed / *r.seconds : double(done) / targetSpp);
        uint32_t passes = 1;
        if (secondsPerPass > 0.0) {
            passes = uint32_t(std::clamp(0.25 / secondsPerPass, 1.0, 1024.0));
            if (r.seconds) passes = std::min(passes, uint32_t((*r.seconds - elapsed) / secondsPerPass) + 1);
        }
        if (!r.seconds) passes = std::min(passes, targetSpp - done);
        const auto batchStart = Clock::now();
        backend.render(passes);
        secondsPerPass = std::max(secondsSince(batchStart) / passes, 1e-6);
    }
    bar.finish();
}

void writeStats(const RenderRequest& r, const Backend& backend, double loadSeconds, const SyncReport& sync) {
    const BackendStats s = backend.stats();
    nlohmann::ordered_json j;
    j["spp"] = s.samplesPerPixel;
    j["seconds"] = s.renderSeconds;
    j["width"] = backend.width();
    j["height"] = backend.height();
    j["backend"] = backend.name();
    j["triangles"] = s.triangles;
    j["instances"] = s.instances;
    j["rays"] = s.rays;
    j["mrays_per_s"] = s.renderSeconds > 0 ? double(s.rays) / s.renderSeconds / 1e6 : 0.0;
    j["nonfinite_samples"] = s.nonfiniteSamples;
    j["load_seconds"] = loadSeconds;
    j["bvh_seconds"] = sync.bvhSeconds;
    j["sync_seconds"] = sync.seconds;
    j["device_memory_bytes"] = backend.deviceMemoryBytes();
    j["toggles"] = toggleStatesJson(backend.toggleStates());
    j["scene"] = r.scenePath;
    writeTextAtomically(r.statsPath, j.dump(2) + "\n");
}

// Fails before rendering, not after, when an output cannot be written.
void checkOutputFolders(const RenderRequest& r) {
    for (const std::string& path : {r.exrPath, r.pngPath, r.statsPath}) {
        if (path.empty()) continue;
        const std::filesystem::path folder = std::filesystem::path(path).parent_path();
        if (!folder.empty() && !std::filesystem::is_directory(folder)) {
            throw std::runtime_error(path + ": folder " + folder.string() + " does not exist");
        }
    }
}

}  // namespace

int runRender(const std::vector<std::string>& args) {
    const RenderRequest r = parseRequest(args);
    checkOutputFolders(r);
    std::unique_ptr<tbb::global_control> threadLimit;
    if (r.threads) {
        threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, *r.threads);
    }
    std::unique_ptr<Backend> backend = createBackend(r.backend);
    ProgressBar bar(!r.quiet);
    SceneInput input = loadSceneInput(r.scenePath, bar);
    Scene& scene = input.scene;
    if (r.size) std::tie(scene.render.width, scene.render.height) = *r.size;
    if (r.seed) scene.render.seed = *r.seed;
    if (r.maxDepth) scene.render.maxDepth = *r.maxDepth;
    const uint32_t targetSpp = r.spp.value_or(scene.render.spp);

    backend->setToggles(r.toggles);
    const SyncReport sync = backend->sync(scene, SceneChanges::All, bar.callback());
    bar.finish();
    accumulate(*backend, r, targetSpp, bar);

    std::vector<float> beauty;
    backend->readBeauty(beauty);
    const BackendStats stats = backend->stats();
    const ImageMetadata metadata = renderMetadata(stats.samplesPerPixel, std::to_string(stats.renderSeconds),
                                                  backend->name(), r.scenePath, "pt-render 0.1");
    if (!r.exrPath.empty()) {
        writeExr(r.exrPath, backend->width(), backend->height(), beauty, metadata);
        std::printf("%s\n", r.exrPath.c_str());
    }
    if (!r.pngPath.empty()) {
        writeDisplayImage(r.pngPath, backend->width(), backend->height(), encodeDisplay8(beauty, DisplaySettings{}), metadata);
        std::printf("%s\n", r.pngPath.c_str());
    }
    if (!r.statsPath.empty()) writeStats(r, *backend, input.loadSeconds, sync);
    if (!r.quiet) {
        std::fprintf(stderr, "%ux%u, %u spp in %.2f s (load %.2f s, BVH %.3f s), %.1f Mrays/s, %llu non-finite samples\n",
                     backend->width(), backend->height(), stats.samplesPerPixel, stats.renderSeconds,
                     input.loadSeconds, sync.bvhSeconds,
                     stats.renderSeconds > 0 ? double(stats.rays) / stats.renderSeconds / 1e6 : 0.0,
                     static_cast<unsigned long long>(stats.nonfiniteSamples));
    }
    return 0;
}

}  // namespace pt::cli
