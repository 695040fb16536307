#pragma once
// RenderScene: the flat, pointer-and-count form of a Scene that per-ray code reads. It owns
// nothing; CompiledScene (host) or a backend's device buffers own the arrays it points at.
// Every struct here is plain data, so the CUDA backend copies the arrays and swaps pointers.
#include <cstdint>

#include "render/kernel/bvh_node.h"
#include "render/kernel/compressed_wide_node.h"
#include "render/kernel/feature_set.h"
#include "render/kernel/leaf_triangle.h"
#include "render/kernel/material.h"
#include "render/kernel/scene_kinds.h"
#include "render/kernel/triangle_block.h"
#include "render/kernel/wide_bvh_node.h"
#include "render/math/affine.h"
#include "render/math/span.h"
#include "render/math/vec.h"
#include "render/sampling/alias_table.h"

namespace pt {

struct TriangleIndices {
    uint32_t v0, v1, v2;  // into RenderScene::positions (already offset per mesh)
};
static_assert(sizeof(TriangleIndices) == 12, "TriangleIndices: 12 bytes");

// One bottom-level acceleration structure: one Mesh, in object space.
struct BlasRef {
    uint32_t nodeOffset;  // into RenderScene::blasNodes; child/leaf indices are relative to it
    uint32_t nodeCount;
    uint32_t primIndexOffset;  // into RenderScene::blasPrimIndices; leaf ranges are relative to it
    uint32_t primitiveOffset;  // first triangle (or sphere) of this mesh in the global arrays
    uint32_t primitiveCount;
    GeometryKind kind;
    uint32_t hasNormals;  // per-vertex normals present
    uint32_t hasUvs;
};
static_assert(sizeof(BlasRef) == 32, "BlasRef: 32 bytes");

struct RenderInstance {
    Affine3 objectToWorld;
    Affine3 worldToObject;
    uint32_t blas;
    uint32_t materialOffset;  // into RenderScene::instanceMaterials: one entry per mesh slot
    uint32_t flipsWinding;    // objectToWorld mirrors (negative determinant)
    // Its triangles are traced in world space, in the merged BLAS (merged_geometry.h), so its
    // hits carry world-space rounding (instance_space.h widens their spawn offsets).
    uint32_t tracedInWorldSpace = 0;
};
static_assert(sizeof(RenderInstance) == 112, "RenderInstance: 112 bytes");

// A triangle of the merged BLAS (merged_geometry.h), as a hit reports it: the instance and
// the mesh-local triangle it is a world-space copy of.
struct MergedTriangle {
    uint32_t instance;   // RenderScene::instances index
    uint32_t primitive;  // triangle of that instance's mesh
};
static_assert(sizeof(MergedTriangle) == 8, "MergedTriangle: 8 bytes");

// RenderScene::mergedBlas when nothing is merged.
constexpr uint32_t kNoMergedBlas = 0xffffffffu;

struct TextureView {
    uint32_t width, height;
    TexelFormat format;
    WrapMode wrapS, wrapT;
    uint32_t nearest;
    uint32_t texelOffset;  // in texels (4 channels each) into texels8 or texelsF
    uint32_t pad = 0;
};
static_assert(sizeof(TextureView) == 32, "TextureView: 32 bytes");

// What next-event estimation can pick from its one alias table (render/lights/emitter_table.h).
enum class LightKind : uint32_t {
    Triangle = 0,     // an emissive triangle of an instance
    Sphere = 1,       // an emissive analytic sphere of a uniformly scaled instance
    Punctual = 2,     // RenderScene::punctualLights[instance]
    Environment = 3,  // the environment (constant colour or importance-sampled image)
};

// One light NEE can pick, with probability weight / RenderScene::emitterTotalWeight. The
// weight estimates power / pi (emitter_table.h says how per kind); the integrator recomputes it
// from the same inputs when a BSDF-sampled ray hits the light, so both strategies agree on its
// probability for MIS.
struct Emitter {
    uint32_t instance;   // Triangle, Sphere: RenderScene::instances index; Punctual: light index
    uint32_t primitive;  // Triangle, Sphere: mesh-local primitive index
    float weight;
    LightKind kind;
};
static_assert(sizeof(Emitter) == 16, "Emitter: 16 bytes");

// A punctual light in world space (Scene's Light, compiled). 48 bytes.
struct PunctualLight {
    Vec3 position;  // point, spot
    LightType type;
    Vec3 direction;  // spot, directional: unit, where the light shines
    float cosInner;  // spot: cos of the inner cone angle
    Vec3 intensity;  // color x intensity: candela (point, spot) or lux (directional)
    float cosOuter;  // spot: cos of the outer cone angle
};
static_assert(sizeof(PunctualLight) == 48, "PunctualLight: 48 bytes");

struct RenderCamera {
    Vec3 origin;
    Vec3 forward;  // unit
    Vec3 right;    // unit, scaled by tan(fov/2) * aspect
    Vec3 up;       // unit, scaled by tan(fov/2)
    float lensRadius;
    float focusDistance;  // > 0
};

struct RenderEnvironment {
    Vec3 color;       // constant radiance x intensity (used when texture < 0)
    int32_t texture;  // equirectangular RGBA32F
    float intensity;
    float rotationRadians;  // about +Y
    // Importance sampling of the image (render/lights/environment_sampling.h): a piecewise-
    // constant density over a distWidth x distHeight grid on the equirect square; 0 x 0 when
    // the environment is a constant colour (sampled uniformly) or black.
    uint32_t distWidth = 0, distHeight = 0;
    float lightWeight = 0.0f;  // its Emitter weight; 0: not in the light table
    uint32_t pad = 0;
};
static_assert(sizeof(RenderEnvironment) == 40, "RenderEnvironment: 40 bytes");

// Integrator switches; each can be flipped at run time so its effect can be measured.
struct IntegratorSettings {
    uint32_t width, height;
    uint32_t maxDepth;
    uint32_t seed;
    uint32_t nextEventEstimation = 1;
    uint32_t multipleImportance = 1;
    uint32_t russianRoulette = 1;
    uint32_t russianRouletteDepth = 3;  // first bounce at which paths may be terminated
    // Firefly clamp: the luminance of each indirect contribution of a sample (light reaching
    // the first hit through another surface) is limited to this; 0 = off. Biased (darkens).
    float clampRadiance = 0.0f;
    uint32_t pixelJitter = 1;  // 0: primary rays through pixel centres (no antialiasing)
};

struct RenderScene {
    // Every array (render/kernel/scene_arrays.h says what each holds).
#define PT_SCENE_ARRAY(Type, name, label) Span<const Type> name;
#include "render/kernel/scene_arrays.h"

    // The merged BLAS's index in blases (merged_geometry.h), or kNoMergedBlas.
    uint32_t mergedBlas = kNoMergedBlas;
    // Some material may let rays through (alpha mask/blend, culled back faces).
    uint32_t transparentMaterials = 0;
    float emitterTotalWeight = 0.0f;  // the sum of emitters' weights
    RenderEnvironment environment;
    RenderCamera camera;
    IntegratorSettings settings;
    uint32_t bruteForce = 0;  // validation: test every primitive, no BVH
    FeatureSet features = 0;  // feature_set.h: what this scene uses (host decisions)
};

}  // namespace pt
