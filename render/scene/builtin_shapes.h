#pragma once
// The unit-sized shapes scene JSON can name. One mesh per shape kind serves every object
// of that kind: objects differ only by transform and material.
#include "render/scene/scene.h"

namespace pt {

Mesh makeUnitSphere();  // analytic: one sphere of radius 1 at the origin
Mesh makeUnitBox();     // 12 triangles spanning [-1, 1]^3, outward normals, per-face UVs
Mesh makeUnitQuad();    // 2 triangles spanning [-1, 1] in X and Z at y = 0, facing +Y

// The scene's mesh for a built-in shape, added on first use.
uint32_t builtinShapeMesh(Scene& scene, ObjectKind kind);

}  // namespace pt
