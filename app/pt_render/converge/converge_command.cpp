// pt-render converge: error against a reference as a function of render time, one curve per
// set of toggles, compared at equal time (DESIGN.md, "Error against run time").
#include <cstdio>
#include <string>
#include <utility>

#include "assets/atomic_file.h"
#include "cli/cli_options.h"
#include "cli/interrupt.h"
#include "cli/output_paths.h"
#include "cli/progress_bar.h"
#include "cli/render_setup.h"
#include "cli/scene_input.h"
#include "cli/toggle_options.h"
#include "pt_render/commands.h"
#include "pt_render/converge/converge_reference.h"
#include "pt_render/converge/converge_report.h"
#include "pt_render/converge/converge_variant.h"
#include "pt_render/svg_plot.h"

namespace pt::cli {

namespace {

constexpr double kDefaultSeconds = 10.0;

struct ConvergeRequest {
    std::string scenePath, referencePath, referenceConstant, csvPath, plotPath;
    double seconds = kDefaultSeconds;
    std::vector<ConvergeVariant> variants;
    RenderSetup setup;
};

// --variant may be given many times, which Options (one value a flag) does not hold: take
// those out first.
std::vector<std::string> takeVariants(std::vector<std::string>& args) {
    std::vector<std::string> specs;
    for (size_t i = 0; i < args.size();) {
        if (args[i] != "--variant") {
            ++i;
            continue;
        }
        if (i + 1 >= args.size()) throw UsageError("--variant needs a value");
        specs.push_back(args[i + 1]);
        args.erase(args.begin() + long(i), args.begin() + long(i) + 2);
    }
    return specs;
}

ConvergeRequest parseRequest(std::vector<std::string> args) {
    std::vector<std::string> specs = takeVariants(args);
    const Options o(args,
                    joined({"--reference", "--reference-constant", "--time", "--csv", "--plot"},
                           renderSetupValuedFlags()),
                    renderSetupSwitches());
    if (o.positional().size() != 1) throw UsageError("expected one SCENE argument");
    ConvergeRequest r;
    r.scenePath = o.positional()[0];
    r.referencePath = o.value("--reference").value_or("");
    r.referenceConstant = o.value("--reference-constant").value_or("");
    if (r.referencePath.empty() == r.referenceConstant.empty()) {
        throw UsageError("give one of --reference REF.exr and --reference-constant R,G,B");
    }
    r.csvPath = o.value("--csv").value_or("");
    r.plotPath = o.value("--plot").value_or("");
    r.seconds = o.positiveNumber("--time").value_or(kDefaultSeconds);
    r.setup = parseRenderSetup(o);
    if (specs.empty()) specs = {"full", "naive:nee=off,mis=off,rr=off"};
    for (const std::string& spec : specs) {
        r.variants.push_back(parseVariant(spec));
        for (size_t i = 0; i + 1 < r.variants.size(); ++i) {
            if (r.variants[i].name == r.variants.back().name)
                throw UsageError("two variants are named " + r.variants[i].name);
        }
    }
    return r;
}

LogLogPlot plotOf(const std::vector<VariantCurve>& curves, const std::string& sceneName) {
    LogLogPlot plot;
    plot.title = "relMSE against render time: " + sceneName;
    plot.xLabel = "render time (s)";
    plot.yLabel = "relMSE";
    plot.guideSlope = -1.0;
    plot.guideLabel = "slope -1";
    for (const VariantCurve& c : curves) {
        PlotSeries series{c.name, {}};
        for (const ErrorPoint& p : c.points) series.points.emplace_back(p.seconds, p.error.relMse);
        plot.series.push_back(std::move(series));
    }
    return plot;
}

}  // namespace

int runConverge(const std::vector<std::string>& args) {
    const ConvergeRequest r = parseRequest(args);
    checkOutputFolder(r.csvPath);
    checkOutputFolder(r.plotPath);
    const auto threadLimit = limitThreads(r.setup);
    ProgressBar bar(!r.setup.quiet);
    SceneInput input = loadSceneInput(r.scenePath, bar);
    applyRenderSetup(r.setup, input.scene);
    const uint32_t width = input.scene.render.width, height = input.scene.render.height;
    const ConvergeReference reference = r.referencePath.empty()
                                            ? constantReference(r.referenceConstant, width, height)
                                            : readReferenceImage(r.referencePath, width, height);

    // Ctrl-C ends the variant under way with the points it has and skips the rest; what was
    // measured is written and summarised, and the exit code says it was cut short.
    const InterruptCatcher interrupt;
    const auto stop = [&] { return interrupt.interrupted(); };
    std::vector<VariantCurve> curves;
    for (const ConvergeVariant& variant : r.variants) {
        if (interrupt.interrupted()) break;
        const auto backend = syncedBackend(r.setup, variant.toggles, input.scene, bar);
        backend->render(1);  // warm-up (thread pools, first-touch pages), not charged to the variant
        if (variant.denoise) {
            backend->setAovs(kDenoiseGuideAovs);  // from the reset on
            backend->setAovSampleCap(settledGuideCap(0, variant.guideSamples));
        }
        backend->resetAccumulation();
        const ProgressFn progress = [&](const std::string&, double f) { bar.update(variant.name, f); };
        std::vector<ErrorPoint> points =
            measureConvergence(*backend, reference.rgba, r.seconds, variant.denoise, progress, stop);
        bar.finish();
        if (points.empty()) break;  // interrupted before its first point
        curves.push_back({variant.name, std::move(points)});
        if (!r.setup.quiet) {
            const ErrorPoint& last = curves.back().points.back();
            std::fprintf(stderr, "%s: %u spp in %.2f s, relMSE %.4g\n", variant.name.c_str(), last.spp,
                         last.seconds, last.error.relMse);
        }
    }
    if (curves.empty()) {
        std::fprintf(stderr, "interrupted before any error was measured: nothing written\n");
        return kInterruptedExitCode;
    }
    if (!r.csvPath.empty()) writeTextAtomically(r.csvPath, convergeCsv(curves));
    if (!r.plotPath.empty()) writeTextAtomically(r.plotPath, svgLogLogPlot(plotOf(curves, r.scenePath)));
    printConvergeSummary(stdout, curves, reference.noiseRelMse);
    if (interrupt.interrupted()) {
        std::fprintf(stderr, "interrupted: measured %zu of %zu variants\n", curves.size(), r.variants.size());
        return kInterruptedExitCode;
    }
    return 0;
}

}  // namespace pt::cli
