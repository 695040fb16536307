#pragma once
// What an edit changed: the kinds of change as bits, and which materials, meshes and instances
// it touched where the edit knows (issue 16). The backend maps them to the least work that
// keeps its copy of the scene correct (DESIGN.md, "Data flow"; render/backend/sync_plan.h).
#include <cstdint>
#include <initializer_list>
#include <vector>

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

// The items of one kind (materials, meshes or instances) an edit touched: `every` where the
// edit did not say which, so that a backend then compares them all.
struct TouchedIds {
    bool every = true;
    std::vector<uint32_t> ids;  // sorted and unique; read only where !every

    static TouchedIds only(std::initializer_list<uint32_t> ids);
    static TouchedIds only(std::vector<uint32_t> ids);
    bool contains(uint32_t id) const;
    // The touched ids below `count`, ascending (0..count-1 where `every`).
    std::vector<uint32_t> below(uint32_t count) const;
    void add(const TouchedIds& other);  // the union
    bool operator==(const TouchedIds& o) const { return every == o.every && (every || ids == o.ids); }
};

// One edit's change, or several edits' merged. Constructible from a bare mask: an edit that
// names no ids touched every item of the kinds its bits name.
struct SceneDelta {
    SceneChangeMask mask = SceneChanges::None;
    TouchedIds materials;  // meaningful under SceneChanges::Materials
    TouchedIds meshes;     // ... under SceneChanges::Geometry
    TouchedIds instances;  // ... under SceneChanges::Transforms

    SceneDelta() = default;
    SceneDelta(SceneChangeMask changes) : mask(changes) {}  // NOLINT: a mask is a delta naming no ids

    bool has(SceneChangeMask bits) const { return (mask & bits) != 0; }
    // Merges a later edit's delta: the bits add; where both touched a kind, the ids add (one
    // side's `every` wins); where only one did, its ids stay.
    SceneDelta& operator|=(const SceneDelta& later);
    // The same delta without the given bits (and without the ids only they gave meaning).
    SceneDelta without(SceneChangeMask bits) const;
    // Equal bits, and equal ids of the kinds the bits name.
    bool operator==(const SceneDelta& o) const;
    bool operator!=(const SceneDelta& o) const { return !(*this == o); }
};

// Deltas of edits that know what they touched.
SceneDelta materialsEdited(std::vector<uint32_t> materials);
SceneDelta meshesMoved(std::vector<uint32_t> meshes);        // vertex positions (Geometry)
SceneDelta instancesMoved(std::vector<uint32_t> instances);  // transforms (Transforms)

}  // namespace pt
