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
                [--max-depth N] [--aov NAME,...|all] [--half] [TOGGLES] [DISPLAY]
      Render SCENE (.json, .gltf, .glb or .obj) progressively; write a linear EXR and/or a
      display-referred PNG (or .jpg, .tif; DISPLAY says how). Prints the paths it wrote. --aov adds AOV layers to the EXR
      (albedo, shading_normal, geometric_normal, depth, position, uv, roughness, metallic,
      emission, instance_id, material_id, bvh_cost, sample_count, variance; only these are
      accumulated); --half writes 16-bit channels (ids, sample_count, depth, position stay float).
  bench SCENE [--backend cpu|cuda] [--size WxH] [--max-depth N] [--runs N] [--spp N]
                [--json OUT.json] [--quiet] [TOGGLES]
      Medians of several runs: traversal Mrays/s (primary, diffuse, shadow; BVH on and off),
      path tracing spp/s and Mpaths/s with each toggle flipped, BLAS/TLAS build and refit
      times (CPU binned SAH; GPU LBVH with the cuda backend), edit-to-first-frame latency, and
      the largest deviation of the backend's image from the CPU's.
  reference SCENE -o REF.exr --spp N [--batches K] [--backend cpu|cuda] [--size WxH] [--seed N]
                [--threads N] [--max-depth N] [--quiet] [TOGGLES]
      A high-spp reference as a float EXR, rendered as K (default 8) independent batches whose
      spread gives the noise of the mean, stored as attributes pt:noise_relmse, pt:noise_rmse.
  converge SCENE (--reference REF.exr | --reference-constant R,G,B) [--time SECONDS]
                [--variant NAME[:KEY=VALUE,...]]... [--csv OUT.csv] [--plot OUT.svg]
                [--backend cpu|cuda] [--size WxH] [--seed N] [--threads N] [--max-depth N] [--quiet]
      Render each variant (default: full, and naive:nee=off,mis=off,rr=off) for SECONDS (default
      10), measuring relMSE, RMSE and MAPE against the reference at log-spaced times; print the
      errors at equal time and flag variants whose error stops falling. Keys: nee, mis, rr, bvh,
      pixel_jitter, megakernel, compaction, material_sort, first_hit_cache (on|off), clamp,
      rebuild_ratio (a number).
  stress [--backend cpu|cuda|all] [--quick] [--only NAME,...] [--csv OUT.csv]
      The robustness suite (scenes/stress/, docs/robustness.md): extreme scales, degenerate
      geometry, materials, lights, accumulation and cameras, each against a stated expectation.
      Exits 1 when a case fails.
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

DISPLAY (the --png image; default: the scene's "color" setting, else the config's default,
  sRGB / Standard in the shipped scenes/ocio/config.ocio):
  --ocio CONFIG (else the scene's config, $OCIO, the shipped one) --display NAME --view NAME
  --look NAME: an OpenColorIO view (shipped: displays sRGB, Rec.1886; views Standard, AgX,
  ACES 1.0 SDR, Raw; looks "Exposure +1", "Exposure -1").
  --tonemap standard|reinhard|aces-fitted|agx [--white-point W]: a built-in operator instead.
  --exposure STOPS (before either), --no-dither (plain rounding to 8 bits).
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
        if (command == "reference") return pt::cli::runReference(args);
        if (command == "converge") return pt::cli::runConverge(args);
        if (command == "stress") return pt::cli::runStress(args);
        std::fprintf(stderr,
                     "pt-render: unknown command \"%s\" (render, bench, reference, converge, stress, export, info, gen; "
                     "see --help)\n",
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
