#pragma once
// Host: the list of emissive triangles that next-event estimation samples, each weighted by
// its power (world-space area x luminance of its emitted radiance), and its alias table.
#include <vector>

#include "render/scene/render_scene.h"

namespace pt {

struct EmitterTable {
    std::vector<Emitter> emitters;
    std::vector<AliasEntry> alias;
    float totalWeight = 0.0f;
};

// Reads geometry, instances and materials from `scene` (which must already point at them).
EmitterTable buildEmitterTable(const RenderScene& scene);

}  // namespace pt
