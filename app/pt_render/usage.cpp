#include "pt_render/usage.h"

namespace pt::cli {

namespace {

enum Footnotes : unsigned { kNone = 0, kToggles = 1, kDisplay = 2 };

struct CommandUsage {
    const char* name;
    const char* text;  // its lines of the usage, as `pt-render --help` lists them
    unsigned footnotes;
};

constexpr CommandUsage kCommands[] = {
    {"render", R"(  render SCENE -o OUT.exr [--png OUT.png] [--spp N | --time SECONDS] [--size WxH]
                [--seed N] [--threads N] [--backend cpu|cuda] [--stats STATS.json] [--quiet]
                [--max-depth N] [--aov NAME,...|all] [--half] [--denoise [--guide-samples N|all]]
                [TOGGLES] [DISPLAY]
      Render SCENE (.json, .gltf, .glb or .obj) progressively; write a linear EXR and/or a
      display-referred PNG (or .jpg, .tif; DISPLAY says how); -o OUT.pfm writes what the PNG
      would show, linear, as a PFM (no layers or metadata; builds without OpenImageIO write
      that). Prints the paths it wrote. --aov adds AOV layers to the EXR
      (albedo, shading_normal, geometric_normal, depth, position, uv, roughness, metallic,
      emission, instance_id, material_id, bvh_cost, sample_count, variance, alpha; only these
      are accumulated); --half writes 16-bit channels (ids, sample_count, depth, position stay
      float). --denoise: the EXR gains denoised.R/G/B beside the raw beauty and the PNG shows
      the denoised image (an a-trous filter guided by albedo, normal, depth, alpha and variance);
      its guides stop accumulating after --guide-samples (default 256; all: every sample), as
      the editor's do, so the scene's specialised kernels run from then on.
      Sequences: --frames A:B[:STEP] [--fps F] [--animation NAME|INDEX] [--skip-existing]
      renders frames A to B of the scene's animation (the first unless named; 24 fps unless
      given), frame f at f / F seconds, each to the outputs with their #### replaced by the
      frame number (-o out_####.exr). Frames are independent: a farm splits a sequence by
      ranges, and --skip-existing leaves frames whose outputs exist (a restarted job resumes).
)",
     kToggles | kDisplay},
    {"bench", R"(  bench SCENE [--backend cpu|cuda] [--size WxH] [--seed N] [--threads N] [--max-depth N]
                [--runs N] [--spp N] [--json OUT.json] [--quiet] [TOGGLES]
      Medians of several runs: traversal Mrays/s (primary, diffuse, shadow; BVH on and off),
      path tracing spp/s and Mpaths/s with each toggle flipped, BLAS/TLAS build and refit
      times (CPU binned SAH; GPU LBVH, PLOC and H-PLOC with the cuda backend), edit-to-first-frame
      latency, and the largest deviation of the backend's image from the CPU's.
)",
     kToggles},
    {"reference",
     R"(  reference SCENE -o REF.exr --spp N [--batches K] [--backend cpu|cuda] [--size WxH] [--seed N]
                [--threads N] [--max-depth N] [--quiet] [TOGGLES]
      A high-spp reference as a float EXR, rendered as K (default 8) independent batches whose
      spread gives the noise of the mean, stored as attributes pt:noise_relmse, pt:noise_rmse.
)",
     kToggles},
    {"converge", R"(  converge SCENE (--reference REF.exr | --reference-constant R,G,B) [--time SECONDS]
                [--variant NAME[:KEY=VALUE,...]]... [--csv OUT.csv] [--plot OUT.svg]
                [--backend cpu|cuda] [--size WxH] [--seed N] [--threads N] [--max-depth N] [--quiet]
      Render each variant (default: full, and naive:nee=off,mis=off,rr=off) for SECONDS (default
      10), measuring relMSE, RMSE and MAPE against the reference at log-spaced times; print the
      errors at equal time and flag variants whose error stops falling. Keys: nee, mis, rr, bvh,
      pixel_jitter, megakernel, path_regeneration, compaction, material_sort, first_hit_cache,
      denoise (on|off: the error of the denoised image), clamp, rebuild_ratio (a number),
      guide_samples (N|all, with denoise=on: as render --guide-samples).
)",
     kNone},
    {"stress", R"(  stress [--backend cpu|cuda|all] [--quick] [--only NAME,...] [--csv OUT.csv]
      The robustness suite (scenes/stress/, docs/robustness.md): extreme scales, degenerate
      geometry, materials, lights, accumulation and cameras, each against a stated expectation.
      Exits 1 when a case fails.
)",
     kNone},
    {"export", R"(  export SCENE -o OUT.json
      Write any loadable scene as scene JSON (atomically; defaults left out).
)",
     kNone},
    {"info", R"(  info SCENE [--json]
      Triangles, meshes, instances, materials, textures, lights, bounds, load and BVH times.
)",
     kNone},
    {"gen", R"(  gen sphere -o OUT.gltf --triangles N [--displace A] [--morph] [--seed S] [--quiet]
  gen skinned -o OUT.gltf --triangles N [--joints J] [--displace A] [--seed S] [--quiet]
  gen field -o OUT.gltf --count N [--mesh IN.gltf|.glb|.obj] [--spacing D] [--seed S] [--quiet]
      Write a synthetic glTF (OUT.gltf + OUT.bin) for scale tests: a displaced sphere of about
      N triangles (up to 10,000,000), with --morph a morph target "bulge" (weight 0; at 1 the
      equator swells 15%); the same stretched into a column skinned to J joints
      (default 8) with a looping 2 s animation "sway"; or N instances (up to 1,000,000) of
      one mesh on a grid.
)",
     kNone},
};

constexpr const char* kToggleText =
    R"(TOGGLES: --no-nee --no-mis --no-rr --clamp X --bvh-off (brute force) --no-jitter
  --no-merge (small instances keep a BLAS each, instead of one world-space BLAS)
  --no-wide-bvh (the CPU walks the binary BLASes instead of their 8-wide form)
  --no-packets (the CPU traces camera rays one at a time, not eight through one walk)
  --megakernel | --wavefront, --regeneration (megakernel: a thread whose path ends starts the
  next at once), --no-compaction, --sort-materials | --no-sort-materials,
  --no-first-hit-cache, --rebuild-ratio R (refit until SAH cost exceeds R x the built one)
  --no-gpu-wide-bvh (the GPU's BLASes get no compressed 8-wide nodes: it walks the binary
  ones; on by default, where the auto schedule times both walks), --no-gpu-first-build (the GPU's
  first frame waits for the host's SAH trees of large meshes, instead of walking trees built
  on the GPU while those build behind it), --no-ploc (the GPU builds BLASes, for first frames
  and rebuilds, as LBVHs instead of by H-PLOC: faster to build, 1.09-1.21x the binned SAH cost
  where H-PLOC is at 1.04-1.14x), --no-leaf-collapse (those GPU builds keep leaves of one
  primitive instead of ending in the SAH's leaves of up to four)
)";

constexpr const char* kDisplayText =
    R"(DISPLAY (the --png image; default: the scene's "color" setting, else the config's default,
  sRGB / Standard in the shipped scenes/ocio/config.ocio):
  --ocio CONFIG (else the scene's config, $OCIO, the shipped one) --display NAME --view NAME
  --look NAME: an OpenColorIO view (shipped: displays sRGB, Rec.1886; views Standard, AgX,
  ACES 1.0 SDR, Raw; looks "Exposure +1", "Exposure -1").
  --tonemap standard|reinhard|aces-fitted|agx [--white-point W]: a built-in operator instead.
  --exposure STOPS (before either), --no-dither (plain rounding to 8 bits).
)";

}  // namespace

std::string fullUsage() {
    std::string text = "usage: pt-render <command> [options]\n\ncommands:\n";
    for (const CommandUsage& c : kCommands) text += c.text;
    return text + "\n" + kToggleText + "\n" + kDisplayText;
}

std::optional<std::string> commandUsage(const std::string& command) {
    for (const CommandUsage& c : kCommands) {
        if (command != c.name) continue;
        std::string text = std::string("usage: pt-render ") + c.name + " [options]\n\n" + c.text;
        if (c.footnotes & kToggles) text += std::string("\n") + kToggleText;
        if (c.footnotes & kDisplay) text += std::string("\n") + kDisplayText;
        return text;
    }
    return std::nullopt;
}

bool asksForHelp(const std::vector<std::string>& args) {
    for (const std::string& a : args) {
        if (a == "--help" || a == "-h") return true;
    }
    return false;
}

}  // namespace pt::cli
