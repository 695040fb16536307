#pragma once
// What an edit changed, as bits; the backend maps them to the least work that keeps its copy
// of the scene correct (DESIGN.md, "Data flow").
#include <cstdint>

namespace pt {

using SceneChangeMask = uint32_t;

namespace SceneChanges {
enum : SceneChangeMask {
    None = 0,
    Camera = 1u << 0,       // camera, depth of field: reset accumulation
    Settings = 1u << 1,     // render settings, toggles: reset accumulation
    Materials = 1u << 2,    // material parameters: re-upload materials (+ lights if emission changed)
    Transforms = 1u << 3,   // instance transforms, visibility, add/remove instance: rebuild TLAS
    Geometry = 1u << 4,     // vertex positions: refit BLAS
    Topology = 1u << 5,     // new meshes or triangles: build BLAS
    Environment = 1u << 6,  // environment color, image, rotation
    Textures = 1u << 7,     // texture images added or replaced
    Display = 1u << 8,      // exposure, view transform, AOV: no reset
    Lights = 1u << 9,       // punctual lights added, removed or edited: rebuild the light table
    All = 0xffffffffu,
};
}  // namespace SceneChanges

}  // namespace pt
