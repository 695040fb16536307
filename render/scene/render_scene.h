#pragma once
// RenderScene: the flat, pointer-and-count form of a Scene that per-ray code reads. It owns
// nothing; CompiledScene (host) or a backend's device buffers own the arrays it points at.
// Every struct here is plain data, so the CUDA backend copies the arrays and swaps pointers.
#include <cstdint>

#include "render/bvh/bvh_node.h"
#include "render/materials/material.h"
#include "render/math/affine.h"
#include "render/math/span.h"
#include "render/math/vec.h"
#include "render/scene/scene.h"

namespace pt {

struct TriangleIndices {
    uint32_t v0, v1, v2;  // into RenderScene::positions (already offset per mesh)
};
static_assert(sizeof(TriangleIndices) == 12, "TriangleIndices: 12 bytes");

// One bottom-level acceleration structure: one Mesh, in object space.
struct BlasRef {
    uint32_t nodeOffset;       // into RenderScene::blasNodes; child/leaf indices are relative to it
    uint32_t nodeCount;
    uint32_t primIndexOffset;  // into RenderScene::blasPrimIndices; leaf ranges are relative to it
    uint32_t primitiveOffset;  // first triangle (or sphere) of this mesh in the global arrays
    uint32_t primitiveCount;
    GeometryKind kind;
    uint32_t hasNormals;       // per-vertex normals present
    uint32_t hasUvs;
};
static_assert(sizeof(BlasRef) == 32, "BlasRef: 32 bytes");

struct RenderInstance {
    Affine3 objectToWorld;
    Affine3 worldToObject;
    uint32_t blas;
    uint32_t materialOffset;   // into RenderScene::instanceMaterials: one entry per mesh slot
    uint32_t flipsWinding;     // objectToWorld mirrors (negative determinant)
    uint32_t pad = 0;
};
static_assert(sizeof(RenderInstance) == 112, "RenderInstance: 112 bytes");

struct TextureView {
    uint32_t width, height;
    TexelFormat format;
    WrapMode wrapS, wrapT;
    uint32_t nearest;
    uint32_t texelOffset;      // in texels (4 channels each) into texels8 or texelsF
    uint32_t pad = 0;
};
static_assert(sizeof(TextureView) == 32, "TextureView: 32 bytes");

// An emissive triangle that next-event estimation can pick, with probability weight / total.
struct Emitter {
    uint32_t instance;
    uint32_t primitive;        // mesh-local triangle index
    float weight;              // world-space area x luminance of emitted radiance
    uint32_t pad = 0;
};

// Walker alias table entry: pick i uniformly, keep it with probability `keep`, else `alias`.
struct AliasEntry {
    float keep;
    uint32_t alias;
};

struct RenderCamera {
    Vec3 origin;
    Vec3 forward;              // unit
    Vec3 right;                // unit, scaled by tan(fov/2) * aspect
    Vec3 up;                   // unit, scaled by tan(fov/2)
    float lensRadius;
    float focusDistance;       // > 0
};

struct RenderEnvironment {
    Vec3 color;                // constant radiance x intensity (used when texture < 0)
    int32_t texture;           // equirectangular RGBA32F
    float intensity;
    float rotationRadians;     // about +Y
};

// Integrator switches; each can be flipped at run time so its effect can be measured.
struct IntegratorSettings {
    uint32_t width, height;
    uint32_t maxDepth;
    uint32_t seed;
    uint32_t nextEventEstimation = 1;
    uint32_t multipleImportance = 1;
    uint32_t russianRoulette = 1;
    uint32_t russianRouletteDepth = 3;  // first bounce at which paths may be terminated
};

struct RenderScene {
    // Geometry, all meshes concatenated.
    Span<const Vec3> positions;
    Span<const Vec3> normals;              // parallel to positions where a mesh has them
    Span<const Vec2> uvs;                  // parallel to positions where a mesh has them
    Span<const TriangleIndices> triangles;
    Span<const Vec4> spheres;              // xyz center, w radius (object space)
    Span<const uint32_t> triangleSlots;    // parallel to triangles: the mesh slot of each
    Span<const uint32_t> sphereSlots;      // parallel to spheres

    // Two-level BVH.
    Span<const BlasRef> blases;
    Span<const BvhNode> blasNodes;
    Span<const uint32_t> blasPrimIndices;
    Span<const RenderInstance> instances;
    Span<const BvhNode> tlasNodes;
    Span<const uint32_t> tlasInstanceIndices;

    // Shading.
    Span<const uint32_t> instanceMaterials;
    Span<const Material> materials;
    Span<const TextureView> textures;
    Span<const uint8_t> texels8;
    Span<const float> texelsF;

    // Lights.
    Span<const Emitter> emitters;
    Span<const AliasEntry> emitterAlias;
    float emitterTotalWeight = 0.0f;
    RenderEnvironment environment;

    RenderCamera camera;
    IntegratorSettings settings;
    uint32_t bruteForce = 0;               // validation: test every primitive, no BVH
};

}  // namespace pt
