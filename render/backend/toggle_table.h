#pragma once
// The renderer's on/off toggles as one table (issue 16): the CLI's flags, the converge and
// stats keys, the editor's checkboxes and undo labels, and the states backends report are all
// read from it, so a new toggle is one row here and one field in IntegratorToggles.
#include <string>
#include <vector>

namespace pt {

// Renderer switches a user can flip to see what each costs or buys. The integrator ones change
// the estimator; the scheduling ones (GPU) change only speed, never the converged image.
struct IntegratorToggles {
    bool nextEventEstimation = true;
    bool multipleImportance = true;
    bool russianRoulette = true;
    bool bruteForce = false;  // BVH off: validation only, refused above a triangle budget
    // Small instances' triangles in one world-space BLAS (render/compile/merged_geometry.h).
    bool mergeInstances = true;
    // The CPU walks 8-wide BLASes collapsed from the binary ones (render/bvh/wide_bvh.h); the
    // GPU walks the binary ones unless gpuWideBvh.
    bool wideBvh = true;
    // The CPU traces closest hits of neighbouring camera rays eight at a time through one walk
    // (render/bvh/packet_traversal.h), where the processor runs AVX2; the same hits as one at
    // a time.
    bool rayPackets = true;
    float clampRadiance = 0.0f;  // firefly clamp on indirect luminance per sample; 0 = off
    // Jitter primary rays inside the pixel (antialiasing). Off: every sample of a pixel starts
    // with the same ray through its centre, which lets the first hit be cached.
    bool pixelJitter = true;
    // CUDA scheduling (the CPU backend runs one path per thread and has none of these).
    // Auto: the first passes of each scene and feature set time both schedules and the rest run
    // the faster (render/backend/schedule_chooser.h); which wins depends on the scene.
    bool autoSchedule = true;
    // Without autoSchedule: one thread runs a whole path; else the wavefront stages.
    bool megakernel = true;
    // Megakernel: a thread whose path ends starts the next path of the pass at once (path
    // regeneration), rather than idling until the other 31 of its warp end theirs. Off by
    // default: it helps where lanes idle most (H100, 1080p: the Cornell box 132.6 against 94.7
    // spp/s) but there the wavefront is faster still (321), and where the megakernel wins it
    // costs coherence (Balloon 774.5 against 784.6, a 1M-triangle sphere 542.8 against 588.1).
    bool pathRegeneration = false;
    // The CUDA kernel variant (render/backend/cuda/kernel_variants.h) by name, to compare
    // variants; "" (the default): the leanest that covers the scene. A variant that does not
    // cover the scene's features is not used: the leanest covering one runs instead.
    std::string kernelVariant = "";
    bool streamCompaction = true;  // wavefront: dead paths leave the queues between bounces
    bool materialSort = false;     // wavefront: paths sorted by material before shading
    bool firstHitCache = true;     // reuse camera-ray hits across passes where the camera allows
    // The GPU's BLASes also get compressed 8-wide nodes (render/bvh/compressed_wide_bvh.h;
    // Ylitie et al. 2017), collapsed from the host's SAH trees on threads behind the first
    // frame, which walks the binary nodes (so a 200k-triangle mesh's first sync stays at 28 ms,
    // where collapsing in the compile made it 71-88 ms, H200). The auto schedule's trial times
    // both walks under each schedule (schedule_chooser.h); without it the compressed nodes are
    // walked where they exist. On an H200 at 1280x720, seven scenes' path tracing to 1024 spp
    // against the binary walk alone: 0.3-1.8% slower on GolfBall, Balloon and a 64-instance
    // field (the trial's own passes; it chose binary), level on a 1M sphere, 2.5% faster on
    // the Cornell box, 1.7% on a barn lamp and 14% with depth of field.
    bool gpuWideBvh = true;
    // The GPU backend's first frame after a full build walks LBVHs built on the GPU for meshes
    // of kGpuFirstBuildMinPrimitives or more, while the host builds their binned SAH trees on a
    // thread behind it and swaps each in when done (the same hits, so the accumulation goes
    // on). With gpuWideBvh the SAH tree's compressed form follows it, collapsed on that thread.
    bool gpuFirstBuild = true;
    // The GPU backend's builds (the first frame's above, and rebuilds once refits have degraded a
    // tree) by H-PLOC (render/backend/cuda/gpu_bvh.h; Benthin et al. 2024), whose trees cost
    // 1.04-1.14x the binned SAH build's on an H200; off: by LBVH, faster to build (1M triangles
    // in 0.42 ms against 0.80 ms) but at 1.09-1.21x.
    bool gpuPloc = true;
    // Those builds end in the SAH leaf rule (BvhLeafCollapse, render/bvh/subtree_collapse.h):
    // subtrees of up to four primitives become leaves where that is cheaper by the SAH, as the
    // binned build's leaves are; off: leaves of one primitive, as the builders make them.
    bool gpuLeafCollapse = true;
    // A refitted BLAS is rebuilt once its SAH cost exceeds this times its cost when last built.
    float rebuildSahRatio = 1.25f;
};

// The on/off fields of IntegratorToggles, by name in code.
enum class ToggleId {
    Nee,
    Mis,
    RussianRoulette,
    Bvh,
    MergeInstances,
    WideBvh,
    RayPackets,
    PixelJitter,
    AutoSchedule,
    Megakernel,
    PathRegeneration,
    Compaction,
    MaterialSort,
    FirstHitCache,
    GpuWideBvh,
    GpuFirstBuild,
    GpuPloc,
    GpuLeafCollapse,
};

// Who can apply a toggle: every backend, or a GPU backend's scheduler only (the CPU runs one
// path per thread and has no schedule to choose).
enum class ToggleScope { Integrator, GpuScheduling };

using ToggleField = bool IntegratorToggles::*;

struct ToggleRow {
    ToggleId id;
    const char* key;        // stats JSON, converge variants, toggle states: "nee"
    const char* label;      // the editor's checkbox: "Next-event estimation"
    const char* editLabel;  // the undo label: "Renderer: next-event estimation off"
    const char* onFlag;     // the CLI flag that turns it on, "" where none (on by default)
    const char* offFlag;    // ... and off, "" where none
    ToggleField field;
    bool inverted;  // the field holds the opposite ("bvh" on is bruteForce off)
    ToggleScope scope;

    bool get(const IntegratorToggles& t) const { return (t.*field) != inverted; }
    void set(IntegratorToggles& t, bool on) const { t.*field = on != inverted; }
};

const std::vector<ToggleRow>& toggleTable();
const ToggleRow& toggleRow(ToggleId id);

}  // namespace pt
