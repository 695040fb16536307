#pragma once
// What one BSDF lobe's sampling routine returns, in the shading frame.
#include "render/math/vec.h"

namespace pt {

struct LobeSample {
    Vec3 wi;           // shading frame, unit
    Vec3 weight;       // f |cos| / pdf of this lobe alone (for delta lobes: the discrete weight)
    float pdf = 0.0f;  // solid-angle density of this lobe; 0 when delta or invalid
    bool valid = false;
    bool delta = false;
    bool transmitted = false;
};

}  // namespace pt
