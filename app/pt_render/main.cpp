// pt-render: the headless command line of the path tracer.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli_options.h"
#include "commands.h"

namespace {

constexpr const char* kUsage = R"(usage: pt-render <command> [options]

commands:
  render SCENE -o OUT.exr [--png OUT.png] [--spp N | --time SECONDS] [--size WxH]
                [--seed N] [--threads N] [--backend cpu|cuda] [--stats STATS.json] [--quiet]
                [--max-depth N] [TOGGLES]
      Render SCENE (.json, .gltf, .glb or .obj) progressively; write a linear EXR and/or a
      display-referred PNG. Prints the paths it wrote.
  bench SCENE [--backend cpu|cuda] [--size WxH] [--max-depth N] [--runs N] [--spp N]
                [--json OUT.json] [--quiet] [TOGGLES]
      Medians of several runs: traversal Mrays/s (primary, diffuse, shadow; BVH on and off),
      path tracing spp/s and Mpaths/s with each toggle flipped, BLAS/TLAS build and refit
      times (CPU binned SAH; GPU LBVH with the cuda backend), edit-to-first-frame latency, and
      the largest deviation of the backend's image from the CPU's.
  export SCENE -o OUT.json
      Write any loadable scene as scene JSON (atomically; defaults left out).
  info SCENE [--json]
      Triangles, meshes, instances, materials, textures, lights, bounds, load and BVH times.
  gen sphere -o OUT.gltf --triangles N [--displace A] [--seed S] [--quiet]
  gen field -o OUT.gltf --count N [--mesh IN.gltf|.glb|.obj] [--spacing D] [--seed S] [--quiet]
      Write a synthetic glTF (OUT.gltf + OUT.bin) for scale tests: a displaced sphere of about
      N triangles (up to 10,000,000), or N instances (up to 1,000,000) of one mesh on a grid.

TOGGLES: --no-nee --no-mis --no-rr --clamp X --bvh-off (brute force) --no-jitter
  --megakernel | --wavefront, --no-compaction, --sort-materials | --no-sort-materials,
  --no-first-hit-cache, --rebuild-ratio R (refit until SAH cost exceeds R x the built one)
)";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
        std::fputs(kUsage, args.empty() ? stderr : stdout);
        return args.empty() ? 2 : 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    try {
        if (command == "render") return pt::cli::runRender(args);
        if (command == "export") return pt::cli::runExport(args);
        if (command == "info") return pt::cli::runInfo(args);
        if (command == "gen") return pt::cli::runGen(args);
        if (command == "bench") return pt::cli::runBench(args);
        std::fprintf(stderr, "pt-render: unknown command \"%s\" (render, bench, export, info, gen; see --help)\n",
                     command.c_str());
        return 2;
    } catch (const pt::cli::UsageError& e) {
        std::fprintf(stderr, "pt-render %s: %s (see --help)\n", command.c_str(), e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pt-render %s: %s\n", command.c_str(), e.what());
        return 1;
    }
}
