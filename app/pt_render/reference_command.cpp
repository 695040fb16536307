// pt-render reference: a high-spp render to compare against, written as a float EXR that
// carries an estimate of its own noise (see batched_render.h for how it is measured).
#include <cstdio>
#include <string>

#include "assets/image/image_write.h"
#include "assets/image/pfm_file.h"
#include "cli/cli_options.h"
#include "cli/interrupt.h"
#include "cli/output_paths.h"
#include "cli/progress_bar.h"
#include "cli/render_setup.h"
#include "cli/scene_input.h"
#include "cli/toggle_options.h"
#include "pt_render/batched_render.h"
#include "pt_render/commands.h"
#include "render/util/image_error.h"

namespace pt::cli {

namespace {

constexpr uint32_t kDefaultBatches = 8;

struct ReferenceRequest {
    std::string scenePath, exrPath;
    uint32_t spp = 0, batches = kDefaultBatches;
    RenderSetup setup;
    IntegratorToggles toggles;
};

ReferenceRequest parseRequest(const std::vector<std::string>& args) {
    const Options o(
        args, joined(joined({"-o", "--spp", "--batches"}, renderSetupValuedFlags()), toggleValuedFlags()),
        joined(renderSetupSwitches(), toggleSwitches()));
    if (o.positional().size() != 1) throw UsageError("expected one SCENE argument");
    ReferenceRequest r;
    r.scenePath = o.positional()[0];
    r.exrPath = o.value("-o").value_or("");
    if (r.exrPath.empty()) throw UsageError("give an output: -o REF.exr");
    const auto spp = o.positiveInt("--spp");
    if (!spp) throw UsageError("give the sample count: --spp N");
    r.spp = *spp;
    r.batches = o.positiveInt("--batches").value_or(kDefaultBatches);
    if (r.batches < 2) throw UsageError("--batches: at least 2 are needed to estimate the noise");
    if (r.spp < r.batches)
        throw UsageError("--spp must be at least --batches (" + std::to_string(r.batches) + ")");
    r.setup = parseRenderSetup(o);
    r.toggles = parseToggles(o);
    return r;
}

}  // namespace

int runReference(const std::vector<std::string>& args) {
    const ReferenceRequest r = parseRequest(args);
    checkOutputFolder(r.exrPath);
    const auto threadLimit = limitThreads(r.setup);
    ProgressBar bar(!r.setup.quiet);
    SceneInput input = loadSceneInput(r.scenePath, bar);
    applyRenderSetup(r.setup, input.scene);
    const auto backend = syncedBackend(r.setup, r.toggles, input.scene, bar);

    // Equal batches keep the variance estimate simple; the count rounds up to a multiple.
    // Ctrl-C drops the batch under way and writes the finished ones (at least two).
    const InterruptCatcher interrupt;
    const uint32_t sppPerBatch = (r.spp + r.batches - 1) / r.batches;
    const BatchedImage image = renderBatches(*backend, input.scene, sppPerBatch, r.batches, bar.callback(),
                                             [&] { return interrupt.interrupted(); });
    bar.finish();
    if (image.interrupted && image.batches < 2) {
        std::fprintf(stderr, "interrupted before two batches were finished: nothing written\n");
        return kInterruptedExitCode;
    }
    const NoiseLevel noise = noiseLevel(image.varianceOfMean, image.mean);
    ImageMetadata metadata = renderMetadata(image.spp, formatFigure(image.renderSeconds), backend->name(),
                                            r.scenePath, "pt-render 0.1");
    metadata.insert(metadata.end(), {{"pt:batches", std::to_string(image.batches)},
                                     {"pt:noise_relmse", formatFigure(noise.relMse)},
                                     {"pt:noise_rmse", formatFigure(noise.rmse)},
                                     {"pt:nonfinite_samples", std::to_string(image.nonfiniteSamples)}});
    // PFM where EXR cannot be written (the GPU machine's build): lossless, but without metadata.
    if (isPfmPath(r.exrPath)) {
        writePfm(r.exrPath, backend->width(), backend->height(), image.mean);
    } else {
        writeExr(r.exrPath, backend->width(), backend->height(), image.mean, metadata);
    }
    std::printf("%s\n", r.exrPath.c_str());
    if (!r.setup.quiet) {
        std::fprintf(
            stderr,
            "%ux%u, %u spp in %u batches, %.2f s; estimated noise of the mean: relMSE %.3g, RMSE %.3g\n",
            backend->width(), backend->height(), image.spp, image.batches, image.renderSeconds, noise.relMse,
            noise.rmse);
    }
    if (image.interrupted) {
        std::fprintf(stderr, "interrupted: wrote the %u finished batches (%u spp)\n", image.batches,
                     image.spp);
        return kInterruptedExitCode;
    }
    return 0;
}

}  // namespace pt::cli
