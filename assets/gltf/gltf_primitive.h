#pragma once
// One glTF mesh primitive read into a self-contained triangle list: accessors read with
// bounds checks, every index checked against the vertex count, every position, normal and
// UV checked finite, strips and fans converted to triangles (winding as the spec's formulas
// give it), normals generated where the file has none. Points and lines are skipped with a
// warning. Internal to pt_assets.
//
// Missing normals are generated *flat* (each triangle gets its own three vertices and its
// geometric normal): the glTF 2.0 spec requires flat normals when NORMAL is absent
// (section 3.7.2.1), and smoothing across the author's hard edges would be wrong for
// low-poly and CAD models. Normals given as zero vectors are replaced by the area-weighted
// normal of the triangles that use the vertex, with one warning per primitive.
//
// Morph targets are read like the attributes they move (same count, finiteness and accessor
// checks, sparse accessors included) and go through the same vertex remapping as the
// positions, so delta i always belongs to position i.
#include <optional>
#include <vector>

#include "assets/gltf/gltf_context.h"
#include "render/animation/skin_vertex.h"

namespace pt {

struct PrimitiveGeometry {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // one per position
    std::vector<Vec2> uvs;      // one per position, or empty (no TEXCOORD_0)
    // One per position, or empty: glTF TANGENT (xyz unit, w = +-1 handedness); a zero vector
    // where the file's tangent is zero. Ignored (empty) without NORMAL, as the spec requires.
    std::vector<Vec4> tangents;
    std::vector<uint32_t> indices;  // triangle list, three per triangle, local to the primitive
    // One per glTF target, in file order (names left empty: they belong to the glTF mesh).
    // positionDeltas: one per position (zero where the target has no POSITION); normalDeltas:
    // one per position, or empty (no NORMAL in the target, or none in the primitive).
    std::vector<MorphTarget> targets;
    // One per position, or empty: the skin's joints and weights (JOINTS_0/WEIGHTS_0, and
    // JOINTS_1/WEIGHTS_1 for influences 5 to 8), as the file gives them (checked against the
    // skin, and normalised, where a node skins the mesh: gltf_skins.h).
    std::vector<JointInfluences> influences;
};

// nullopt when the primitive is skipped (a warning says why); InputError when malformed.
std::optional<PrimitiveGeometry> readGltfPrimitive(const GltfContext& ctx, size_t mesh, size_t primitive);

}  // namespace pt
