// pt-render render: progressive offline render to EXR and/or PNG.
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "assets/atomic_file.h"
#include "assets/image/exr_layers.h"
#include "assets/image/image_metadata.h"
#include "assets/image/image_write.h"
#include "assets/image/pfm_file.h"
#include "assets/input_error.h"
#include "cli/cli_options.h"
#include "cli/display_options.h"
#include "cli/frame_sequence.h"
#include "cli/guide_samples.h"
#include "cli/interrupt.h"
#include "cli/progress_bar.h"
#include "cli/render_setup.h"
#include "cli/scene_input.h"
#include "cli/toggle_options.h"
#include "pt_render/commands.h"
#include "render/backend/backend.h"
#include "render/compile/scene_features.h"
#include "render/display/display_transform.h"
#include "render/scene/scene_animation.h"
#include "render/util/stopwatch.h"

namespace pt::cli {

namespace {

struct RenderRequest {
    std::string scenePath, exrPath, pngPath, statsPath;
    RenderSetup setup;  // --backend --size --seed --max-depth --threads --quiet
    std::optional<uint32_t> spp;
    std::optional<double> seconds;
    IntegratorToggles toggles;
    AovMask aovs = 0;   // --aov: EXR layers beside the beauty (only these are accumulated)
    bool half = false;  // --half: 16-bit EXR channels (exr_layers.h says which stay float)
    // --denoise: the EXR gains a denoised layer beside the raw beauty, the PNG shows the
    // denoised image; the denoiser's guides are accumulated for it, up to --guide-samples
    // (0: with every sample).
    bool denoise = false;
    uint32_t guideSamples = kSettledGuideSamples;
    DisplayRequest display;  // --png: how linear becomes display pixels (display_options.h)
    // --frames A:B[:STEP]: a sequence, frame f posed at f / fps seconds of --animation (a name
    // or an index; the first where not given), each frame to the outputs with #### replaced.
    std::optional<FrameRange> frames;
    double fps = 24.0;
    std::string animation;
    bool skipExisting = false;  // --skip-existing: frames whose outputs all exist are left
};

void parseExrOptions(const Options& o, RenderRequest& r) {
    if (const std::optional<std::string> list = o.value("--aov")) {
        try {
            r.aovs = parseAovList(*list);
        } catch (const InputError& e) {
            throw UsageError(std::string("--aov: ") + e.what());
        }
    }
    r.half = o.has("--half");
    if ((r.exrPath.empty() || isPfmPath(r.exrPath)) && (o.has("--aov") || r.half))
        throw UsageError("--aov and --half need -o OUT.exr");
}

void parseSequenceOptions(const Options& o, RenderRequest& r) {
    if (const std::optional<std::string> frames = o.value("--frames")) r.frames = parseFrameRange(*frames);
    if (!r.frames && (o.has("--fps") || o.has("--animation") || o.has("--skip-existing")))
        throw UsageError("--fps, --animation and --skip-existing apply to --frames A:B[:STEP]");
    if (const std::optional<double> fps = o.positiveNumber("--fps")) r.fps = *fps;
    r.animation = o.value("--animation").value_or("");
    r.skipExisting = o.has("--skip-existing");
    if (!r.frames) return;
    for (const std::string& path : {r.exrPath, r.pngPath}) {
        if (!path.empty()) framePath(path, 0);  // a sequence's outputs need their #### (UsageError)
    }
}

RenderRequest parseRequest(const std::vector<std::string>& args) {
    const Options o(args,
                    joined(joined({"-o", "--png", "--spp", "--time", "--stats", "--aov", "--frames", "--fps",
                                   "--animation", "--guide-samples"},
                                  renderSetupValuedFlags()),
                           joined(toggleValuedFlags(), displayValuedFlags())),
                    joined(joined(joined({"--half", "--denoise", "--skip-existing"}, renderSetupSwitches()),
                                  toggleSwitches()),
                           displaySwitches()));
    if (o.positional().size() != 1) throw UsageError("expected one SCENE argument");
    RenderRequest r;
    r.scenePath = o.positional()[0];
    r.exrPath = o.value("-o").value_or("");
    r.pngPath = o.value("--png").value_or("");
    if (r.exrPath.empty() && r.pngPath.empty())
        throw UsageError("give an output: -o OUT.exr and/or --png OUT.png");
    r.statsPath = o.value("--stats").value_or("");
    r.setup = parseRenderSetup(o);
    r.spp = o.positiveInt("--spp");
    r.seconds = o.positiveNumber("--time");
    if (r.spp && r.seconds) throw UsageError("--spp and --time exclude each other");
    r.toggles = parseToggles(o);
    parseExrOptions(o, r);
    r.display = parseDisplayOptions(o);
    if (r.display.anyGiven && r.pngPath.empty())
        throw UsageError("display flags apply to --png OUT.png; give one");
    r.denoise = o.has("--denoise");
    if (o.value("--guide-samples") && !r.denoise)
        throw UsageError("--guide-samples applies to --denoise; give it");
    r.guideSamples = guideSamplesOption(o);
    parseSequenceOptions(o, r);
    return r;
}

// Renders until the sample or time budget is met, or Ctrl-C, in batches of about a quarter
// second so the progress bar moves and an interrupt is answered within one; with --time no
// batch is planned past the budget.
// `progress` maps this render's fraction done onto the bar (a sequence's frame is a part of
// the whole, so the ETA is the sequence's).
struct BarSpan {
    const char* stage = "render";
    double offset = 0.0, scale = 1.0;
};

void accumulate(Backend& backend, const RenderRequest& r, uint32_t targetSpp, ProgressBar& bar,
                const InterruptCatcher& interrupt, const BarSpan& progress) {
    const auto start = Clock::now();
    double secondsPerPass = 0.0;  // unknown until the first batch
    for (;;) {
        const double elapsed = secondsSince(start);
        const uint32_t done = backend.stats().samplesPerPixel;
        if (r.seconds ? elapsed >= *r.seconds : done >= targetSpp) break;
        if (interrupt.interrupted()) break;
        const double fraction = r.seconds ? elapsed / *r.seconds : double(done) / targetSpp;
        bar.update(progress.stage, progress.offset + progress.scale * fraction);
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
    j["aovs"] = aovListText(backend.aovs());
    j["aov_bytes"] = backend.aovBytes();
    j["toggles"] = toggleStatesJson(backend.toggleStates());
    j["features"] = featureNames(s.features);
    j["kernel_variant"] = s.kernelVariant;  // "" where the code is not specialised (CPU)
    j["kernel_features"] = featureNames(s.kernelFeatures);
    if (!s.schedule.empty()) {  // GPU backends: which schedule ran, and under auto what each measured
        j["schedule"] = s.schedule;
        if (s.megakernelRate > 0.0) j["megakernel_spp_per_s"] = s.megakernelRate;
        if (s.wavefrontRate > 0.0) j["wavefront_spp_per_s"] = s.wavefrontRate;
        if (!s.walk.empty()) j["walk"] = s.walk;  // compressed 8-wide or binary BLAS nodes
    }
    j["scene"] = r.scenePath;
    writeTextAtomically(r.statsPath, j.dump(2) + "\n");
}

// The beauty and the AOVs asked for as one layered EXR, with the camera in the metadata, and
// `denoised` (RGBA; empty: none) as its denoised layer.
void writeRenderExr(const RenderRequest& r, const Backend& backend, const Camera& camera,
                    const ImageMetadata& metadata, const std::vector<float>& denoised) {
    LayeredExr exr = layeredExr(readRenderedImages(backend, r.aovs),
                                r.half ? ExrPixelType::Half : ExrPixelType::Float, camera, metadata);
    exr.denoised = denoised;
    writeLayeredExr(r.exrPath, exr);
    if (r.setup.quiet) return;
    std::string channels = "R G B A";
    for (const AovImage& layer : exr.aovs) {
        for (const std::string& name : aovExrChannelNames(layer.aov)) channels += " " + name;
    }
    if (!exr.denoised.empty()) channels += " denoised.R denoised.G denoised.B";
    std::fprintf(stderr, "%s: %s channels %s\n", r.exrPath.c_str(), r.half ? "half" : "float",
                 channels.c_str());
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

// What one render (a frame of a sequence, or the whole command) leaves behind: the images
// and stats `fr` names, and the summary line.
struct FrameContext {
    Backend& backend;
    const Scene& scene;
    const std::optional<DisplayProcessor>& display;
    double loadSeconds;
};

void writeOutputs(const RenderRequest& fr, const FrameContext& c, const SyncReport& sync) {
    Backend& backend = c.backend;
    std::vector<float> shown;  // what the PNG shows: the beauty, or with --denoise the denoised one
    if (fr.denoise) {
        backend.readDenoised(shown);
    } else {
        backend.readBeauty(shown);
    }
    const BackendStats stats = backend.stats();
    const ImageMetadata metadata = renderMetadata(stats.samplesPerPixel, std::to_string(stats.renderSeconds),
                                                  backend.name(), fr.scenePath, "pt-render 0.1");
    if (!fr.exrPath.empty()) {
        ImageMetadata exrMetadata = metadata;
        if (c.display) {  // the OCIO config and view of the PNG beside it
            const ImageMetadata view = displayMetadata(*c.display, fr.display.dither);
            exrMetadata.insert(exrMetadata.end(), view.begin(), view.end());
        }
        if (isPfmPath(fr.exrPath)) {
            // PFM where EXR cannot be written (the GPU machine's build): one linear RGB image,
            // what the PNG shows before its display transform, without layers or metadata.
            writePfm(fr.exrPath, backend.width(), backend.height(), shown);
        } else {
            writeRenderExr(fr, backend, c.scene.camera, exrMetadata,
                           fr.denoise ? shown : std::vector<float>{});
        }
        std::printf("%s\n", fr.exrPath.c_str());
    }
    if (!fr.pngPath.empty()) {
        ImageMetadata pngMetadata = metadata;
        const ImageMetadata displayInfo = displayMetadata(*c.display, fr.display.dither);
        pngMetadata.insert(pngMetadata.end(), displayInfo.begin(), displayInfo.end());
        writeDisplayImage(fr.pngPath, backend.width(), backend.height(),
                          c.display->encode8(shown, backend.width(), fr.display.dither), pngMetadata);
        std::printf("%s\n", fr.pngPath.c_str());
    }
    if (!fr.statsPath.empty()) writeStats(fr, backend, c.loadSeconds, sync);
    if (!fr.setup.quiet) {
        std::fprintf(
            stderr,
            "%ux%u, %u spp in %.2f s (load %.2f s, BVH %.3f s), %.1f Mrays/s, %llu non-finite samples\n",
            backend.width(), backend.height(), stats.samplesPerPixel, stats.renderSeconds, c.loadSeconds,
            sync.bvhSeconds, stats.renderSeconds > 0 ? double(stats.rays) / stats.renderSeconds / 1e6 : 0.0,
            static_cast<unsigned long long>(stats.nonfiniteSamples));
    }
}

// Renders one frame into `fr`'s outputs; the exit code (interrupted, or 0).
int renderFrame(const RenderRequest& fr, const FrameContext& c, const SyncReport& sync, uint32_t targetSpp,
                ProgressBar& bar, const InterruptCatcher& interrupt, const BarSpan& span) {
    accumulate(c.backend, fr, targetSpp, bar, interrupt, span);
    const uint32_t samples = c.backend.stats().samplesPerPixel;
    if (interrupt.interrupted() && samples == 0) {
        bar.finish();
        std::fprintf(stderr, "interrupted before the first sample: nothing written\n");
        return kInterruptedExitCode;
    }
    if (!fr.frames) bar.finish();
    writeOutputs(fr, c, sync);
    if (interrupt.interrupted()) {
        bar.finish();
        std::fprintf(stderr, "interrupted: wrote the %u spp rendered so far\n", samples);
        return kInterruptedExitCode;
    }
    return 0;
}

// The request for frame `frame` of a sequence: its outputs' #### replaced (stats too, where
// that path has them; else each frame rewrites it).
RenderRequest frameRequest(const RenderRequest& r, int64_t frame) {
    RenderRequest fr = r;
    for (std::string* path : {&fr.exrPath, &fr.pngPath, &fr.statsPath}) {
        if (hasFrameNumber(*path)) *path = framePath(*path, frame);
    }
    return fr;
}

bool outputsExist(const RenderRequest& fr) {
    for (const std::string& path : {fr.exrPath, fr.pngPath}) {
        if (!path.empty() && !std::filesystem::exists(path)) return false;
    }
    return true;
}

int renderSequence(const RenderRequest& r, Scene& scene, const FrameContext& c, uint32_t targetSpp,
                   ProgressBar& bar, const InterruptCatcher& interrupt) {
    const std::vector<int64_t> frames = r.frames->frames();
    const std::vector<int32_t> chosen = chooseAnimations(scene, r.animation);
    for (size_t i = 0; i < frames.size(); ++i) {
        const RenderRequest fr = frameRequest(r, frames[i]);
        if (r.skipExisting && outputsExist(fr)) {
            if (!r.setup.quiet)
                std::fprintf(stderr, "frame %lld: done before, skipped\n", (long long)frames[i]);
            continue;
        }
        const float time = float(double(frames[i]) / r.fps);
        const SyncReport sync =
            c.backend.sync(scene, poseAnimations(scene, chosen, time, skinningSite(c.backend)));
        const BarSpan span{"frames", double(i) / double(frames.size()), 1.0 / double(frames.size())};
        if (const int code = renderFrame(fr, c, sync, targetSpp, bar, interrupt, span)) return code;
    }
    bar.finish();
    return 0;
}

}  // namespace

int runRender(const std::vector<std::string>& args) {
    const RenderRequest r = parseRequest(args);
    checkOutputFolders(r);
    const std::unique_ptr<tbb::global_control> threadLimit = limitThreads(r.setup);
    std::unique_ptr<Backend> backend = createBackend(r.setup.backend);
    const InterruptCatcher interrupt;  // Ctrl-C from here on writes what was rendered
    ProgressBar bar(!r.setup.quiet);
    SceneInput input = loadSceneInput(r.scenePath, bar);
    Scene& scene = input.scene;
    applyRenderSetup(r.setup, scene);
    const uint32_t targetSpp = r.spp.value_or(scene.render.spp);
    // Before rendering, so that a bad config or view name fails fast.
    std::optional<DisplayProcessor> display;
    if (!r.pngPath.empty()) display.emplace(makeDisplayProcessor(r.display, scene.color));

    backend->setToggles(r.toggles);
    backend->setAovs(r.aovs |
                     (r.denoise ? kDenoiseGuideAovs : 0u));  // before the sync, whose reset allocates them
    if (r.denoise) backend->setAovSampleCap(settledGuideCap(r.aovs, r.guideSamples));  // --aov layers in full
    const SyncReport sync = backend->sync(scene, SceneChanges::All, bar.callback());
    bar.finish();
    const FrameContext context{*backend, scene, display, input.loadSeconds};
    if (r.frames) return renderSequence(r, scene, context, targetSpp, bar, interrupt);
    return renderFrame(r, context, sync, targetSpp, bar, interrupt, BarSpan{});
}

}  // namespace pt::cli
