// pathtracer: the editor. Opens SCENE (scene JSON, glTF or OBJ; or nothing, then File > Open or
// drop a file on the window) and renders it progressively while it is edited.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>

#include "cli/cli_options.h"
#include "editor/ui/editor_window.h"

namespace {

constexpr const char* kUsage =
    "usage: pathtracer [SCENE] [--backend cpu|cuda] [--size WxH] [--spp N] [--frames N] [--screenshot "
    "OUT.png]\n"
    "                  [--reference REF.exr] [--ocio CONFIG.ocio] [--latency-log OUT.jsonl] "
    "[--no-frame-wait]\n"
    "  --backend     renderer (default: cuda where a usable GPU is, else cpu)\n"
    "  --size        render resolution, overriding the scene's\n"
    "  --spp         stop accumulating at N samples per pixel\n"
    "  --frames      exit after N displayed frames with new samples (or when --spp is reached)\n"
    "  --screenshot  write the window as PNG after --frames, and on every F12 (numbered)\n"
    "  --reference   an image (e.g. from pt-render reference) to plot the error against, live\n"
    "  --ocio        OpenColorIO config for the viewport (default: the scene's, else $OCIO, else the shipped "
    "one)\n"
    "  --latency-log each edit's time from input to the swapped frame that shows it, as JSON lines\n"
    "  --no-frame-wait  swap without waiting a few ms for the samples of an edit made in that frame\n"
    "                (they then show a refresh later; for latency comparisons)\n";

pt::editor::EditorOptions parse(const std::vector<std::string>& args) {
    const pt::cli::Options o(args,
                             {"--backend", "--size", "--spp", "--frames", "--screenshot", "--reference",
                              "--ocio", "--latency-log"},
                             {"--help", "-h", "--no-frame-wait"});
    if (o.has("--help") || o.has("-h")) {
        std::fputs(kUsage, stdout);
        std::exit(0);
    }
    if (o.positional().size() > 1) throw pt::cli::UsageError("expected at most one SCENE argument");
    pt::editor::EditorOptions options;
    if (!o.positional().empty()) options.scenePath = o.positional()[0];
    options.backend = o.value("--backend").value_or("");
    if (const auto size = o.size("--size")) std::tie(options.width, options.height) = *size;
    options.spp = o.positiveInt("--spp").value_or(0);
    if (const auto frames = o.nonNegativeInt("--frames")) options.frames = *frames;
    options.screenshotPath = o.value("--screenshot").value_or("");
    options.referencePath = o.value("--reference").value_or("");
    options.ocioPath = o.value("--ocio").value_or("");
    options.latencyLogPath = o.value("--latency-log").value_or("");
    options.frameWait = !o.has("--no-frame-wait");
    return options;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const pt::editor::EditorOptions options = parse(std::vector<std::string>(argv + 1, argv + argc));
        return pt::editor::runEditor(options);
    } catch (const pt::cli::UsageError& e) {
        std::fprintf(stderr, "pathtracer: %s\n%s", e.what(), kUsage);
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pathtracer: %s\n", e.what());
        return 1;
    }
}
