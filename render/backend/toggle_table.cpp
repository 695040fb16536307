#include "render/backend/toggle_table.h"

namespace pt {

const std::vector<ToggleRow>& toggleTable() {
    using S = ToggleScope;
    using T = IntegratorToggles;
    static const std::vector<ToggleRow> rows = {
        {ToggleId::Nee, "nee", "Next-event estimation", "next-event estimation", "", "--no-nee",
         &T::nextEventEstimation, false, S::Integrator},
        {ToggleId::Mis, "mis", "Multiple importance sampling", "MIS", "", "--no-mis", &T::multipleImportance,
         false, S::Integrator},
        {ToggleId::RussianRoulette, "rr", "Russian roulette", "Russian roulette", "", "--no-rr",
         &T::russianRoulette, false, S::Integrator},
        {ToggleId::Bvh, "bvh", "BVH (off: brute force, validation only)", "BVH", "", "--bvh-off",
         &T::bruteForce, true, S::Integrator},
        {ToggleId::MergeInstances, "merge_instances", "Merge small instances (one world-space BLAS)",
         "merged instances", "", "--no-merge", &T::mergeInstances, false, S::Integrator},
        {ToggleId::WideBvh, "wide_bvh", "8-wide BVH (CPU traversal)", "8-wide BVH", "", "--no-wide-bvh",
         &T::wideBvh, false, S::Integrator},
        {ToggleId::RayPackets, "ray_packets", "8-ray packets (CPU camera rays)", "8-ray packets", "",
         "--no-packets", &T::rayPackets, false, S::Integrator},
        {ToggleId::PixelJitter, "pixel_jitter", "Pixel jitter (antialiasing)", "pixel jitter", "",
         "--no-jitter", &T::pixelJitter, false, S::Integrator},
        // No flag of its own: naming a schedule (--megakernel, --wavefront) turns it off.
        {ToggleId::AutoSchedule, "auto_schedule", "Auto schedule (time both, run the faster)",
         "auto schedule", "", "", &T::autoSchedule, false, S::GpuScheduling},
        {ToggleId::Megakernel, "megakernel", "Megakernel (else wavefront)", "megakernel", "--megakernel",
         "--wavefront", &T::megakernel, false, S::GpuScheduling},
        {ToggleId::PathRegeneration, "path_regeneration", "Path regeneration (megakernel)",
         "path regeneration", "--regeneration", "", &T::pathRegeneration, false, S::GpuScheduling},
        {ToggleId::Compaction, "compaction", "Stream compaction", "stream compaction", "", "--no-compaction",
         &T::streamCompaction, false, S::GpuScheduling},
        {ToggleId::MaterialSort, "material_sort", "Material sort", "material sort", "--sort-materials",
         "--no-sort-materials", &T::materialSort, false, S::GpuScheduling},
        {ToggleId::GpuWideBvh, "gpu_wide_bvh", "Compressed 8-wide BVH (GPU traversal)",
         "compressed 8-wide BVH", "--gpu-wide-bvh", "--no-gpu-wide-bvh", &T::gpuWideBvh, false,
         S::GpuScheduling},
        {ToggleId::GpuFirstBuild, "gpu_first_build", "First frame from a GPU-built BVH (SAH behind it)",
         "GPU first build", "", "--no-gpu-first-build", &T::gpuFirstBuild, false, S::GpuScheduling},
        {ToggleId::GpuPloc, "gpu_ploc", "GPU BVH builds by H-PLOC (else LBVH)", "H-PLOC GPU builds", "",
         "--no-ploc", &T::gpuPloc, false, S::GpuScheduling},
        {ToggleId::GpuLeafCollapse, "gpu_leaf_collapse", "GPU BVH builds end in SAH leaves (of up to 4)",
         "GPU BVH leaf collapse", "", "--no-leaf-collapse", &T::gpuLeafCollapse, false, S::GpuScheduling},
        {ToggleId::FirstHitCache, "first_hit_cache", "First-hit cache", "first-hit cache", "",
         "--no-first-hit-cache", &T::firstHitCache, false, S::GpuScheduling},
    };
    return rows;
}

const ToggleRow& toggleRow(ToggleId id) {
    for (const ToggleRow& row : toggleTable()) {
        if (row.id == id) return row;
    }
    return toggleTable().front();  // unreachable: every id has a row (toggle_table_test.cpp)
}

}  // namespace pt
