#pragma once
// Hit: what closest-hit traversal returns. 20 bytes, over the 16 of STYLE.md rule 8 by the
// instance id: packing instance and primitive into 32 bits would cap either instances
// (scenes of thousands) or triangles per mesh (10M), and both are needed.
#include <cstdint>

#include "render/math/hd.h"

namespace pt {

struct Hit {
    float t;             // ray parameter; the world-space ray direction need not be unit length
    float u, v;          // triangle barycentrics of v1 and v2; spheres: unused
    uint32_t primitive;  // mesh-local triangle or sphere index
    uint32_t instance;   // RenderScene::instances index; kNoHit when nothing was hit

    static constexpr uint32_t kNoHit = 0xffffffffu;
    PT_HD bool valid() const { return instance != kNoHit; }
};
static_assert(sizeof(Hit) == 20, "Hit: 20 bytes");

}  // namespace pt
