#pragma once
// Fields of instances for `pt-render gen field`: one mesh placed on a jittered grid in the
// XZ plane, each copy with its own random rotation and uniform scale.
#include <cstdint>
#include <optional>
#include <vector>

#include "pt_render/gen/gen_scene.h"

namespace pt::cli {

struct FieldSpec {
    uint32_t count = 1000;
    std::optional<double> spacing;  // grid step; default 4x the mesh's bounding radius
    uint64_t seed = 0;
};

struct FieldLayout {
    std::vector<GenNode> instances;
    double spacing = 0.0;  // the grid step used
    Vec3 lo, hi;           // bounds of the whole field (each copy by its bounding sphere)
};

// Scales are in [0.7, 1.2] and jitter within 20% of the step, so at the default spacing the
// copies never touch. The mesh is rotated and scaled about the centre of its bounds.
FieldLayout layoutField(const Mesh& mesh, const FieldSpec& spec);

}  // namespace pt::cli
