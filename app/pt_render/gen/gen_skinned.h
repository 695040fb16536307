#pragma once
// A skinned column for `pt-render gen skinned`: the displaced cube-sphere stretched along Y,
// skinned to a chain of joints up its axis, with one looping animation ("sway") that bends
// the chain back and forth: the generated skinned mesh of any size that per-frame skinning and
// refit figures are measured on (issue 19).
#include <cstdint>

#include "pt_render/gen/gen_scene.h"
#include "render/util/progress.h"

namespace pt::cli {

struct SkinnedSpec {
    uint32_t targetTriangles = 1000;  // as SphereSpec
    double amplitude = 0.1;
    uint64_t seed = 0;
    uint32_t joints = 8;          // 2 or more, up the column
    float swayRadians = 0.2f;     // each joint's largest turn from rest, about Z
    float periodSeconds = 2.0f;   // the animation loops after this
    uint32_t keysPerPeriod = 24;  // linear keys
};

constexpr float kSkinnedColumnHalfHeight = 3.0f;  // the column spans y in [-3, 3] at rest

// The column (mesh, one instance), its skin and animation, and a camera and lights that frame
// it at every pose.
GenScene generateSkinnedColumn(const SkinnedSpec& spec, const ProgressFn& progress = {});

}  // namespace pt::cli
