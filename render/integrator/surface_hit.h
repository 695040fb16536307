#pragma once
// From a Hit to what shading needs: world position, geometric and shading normals, UV and
// material. Positions are interpolated from the primitive, not taken as origin + t * dir,
// so they lie on the surface to float precision however far the ray travelled; positionError
// bounds what precision that is (instance_space.h), for offsetRayOrigin().
//
// The front face is the counter-clockwise side in object space (outside, for spheres). A
// mirroring instance transform keeps it the front face (glTF: a negative determinant makes
// the clockwise side the front in world space), so normals go through the inverse transpose
// and are never flipped for mirroring; the emitter code agrees (emitter_sample.h).
#include "render/bvh/hit.h"
#include "render/bvh/instance_space.h"
#include "render/kernel/render_scene.h"
#include "render/lights/sphere_light.h"
#include "render/math/ray.h"

namespace pt {

struct SurfaceHit {
    Vec3 position;
    Vec3 positionError;    // per axis, for offsetRayOrigin()
    Vec3 geometricNormal;  // unit, on the front side
    Vec3 shadingNormal;    // unit, same hemisphere as geometricNormal
    Vec2 uv;
    bool frontFace;      // the ray arrived from the front side
    uint32_t material;   // RenderScene::materials index
    uint32_t instance;   // RenderScene::instances index
    uint32_t primitive;  // mesh-local triangle or sphere index
    GeometryKind kind;
};

template <FeatureSet kF = kAllFeatures>
PT_HD SurfaceHit triangleSurface(const RenderScene& scene, const RenderInstance& inst, const BlasRef& blas,
                                 const Hit& hit) {
    SurfaceHit s{};
    const TriangleIndices t = scene.triangles[blas.primitiveOffset + hit.primitive];
    const float b0 = 1.0f - hit.u - hit.v;
    const Vec3 p0 = scene.positions[t.v0], p1 = scene.positions[t.v1], p2 = scene.positions[t.v2];
    const SurfacePoint point = triangleSurfacePoint(inst, p0, p1, p2, {b0, hit.u, hit.v});
    s.position = point.position;
    s.positionError = point.error;
    const Vec3 nObject = cross(p1 - p0, p2 - p0);
    const Vec3 ng = normalize(inst.worldToObject.transformNormalByInverse(nObject));
    s.geometricNormal = ng;
    s.shadingNormal = ng;
    if (blas.hasNormals) {
        const Vec3 n = scene.normals[t.v0] * b0 + scene.normals[t.v1] * hit.u + scene.normals[t.v2] * hit.v;
        Vec3 ns = inst.worldToObject.transformNormalByInverse(n);
        if (lengthSquared(ns) > 0.0f) {
            ns = normalize(ns);
            // Vertex normals that disagree with the face would send light through it.
            s.shadingNormal = dot(ns, ng) > 0.0f ? ns : ng;
        }
    }
    // UVs feed textures and AOVs alone; kernels with neither never read them.
    constexpr bool kReadsUv = hasFeature<kF>(feature::kTextures | feature::kNormalMap | feature::kAlphaMask |
                                             feature::kAlphaBlend | feature::kAovs);
    if (kReadsUv && blas.hasUvs)
        s.uv = scene.uvs[t.v0] * b0 + scene.uvs[t.v1] * hit.u + scene.uvs[t.v2] * hit.v;
    s.material = scene.instanceMaterials[inst.materialOffset +
                                         scene.triangleSlots[blas.primitiveOffset + hit.primitive]];
    s.kind = GeometryKind::Triangles;
    return s;
}

PT_HD SurfaceHit sphereSurface(const RenderScene& scene, const RenderInstance& inst, const BlasRef& blas,
                               const Ray& worldRay, const Hit& hit) {
    SurfaceHit s{};
    const Vec4 sphere = scene.spheres[blas.primitiveOffset + hit.primitive];
    const Vec3 o = objectSpacePoint(inst, worldRay.origin);
    const Vec3 d = inst.worldToObject.transformVector(worldRay.direction);
    // Project back onto the sphere: removes the error of o + t d.
    const Vec3 radial = normalize(o + d * hit.t - sphere.xyz());
    s.position = inst.objectToWorld.transformPoint(sphere.xyz() + radial * sphere.w);
    s.positionError = spherePointError(inst, sphere);
    s.geometricNormal = normalize(inst.worldToObject.transformNormalByInverse(radial));
    s.shadingNormal = s.geometricNormal;
    s.uv = sphereUv(radial);
    s.material =
        scene
            .instanceMaterials[inst.materialOffset + scene.sphereSlots[blas.primitiveOffset + hit.primitive]];
    s.kind = GeometryKind::Spheres;
    return s;
}

template <FeatureSet kF = kAllFeatures>
PT_HD SurfaceHit surfaceAt(const RenderScene& scene, const Ray& worldRay, const Hit& hit) {
    const RenderInstance& inst = scene.instances[hit.instance];
    const BlasRef& blas = scene.blases[inst.blas];
    SurfaceHit s = hasFeature<kF>(feature::kSpheres) && blas.kind == GeometryKind::Spheres
                       ? sphereSurface(scene, inst, blas, worldRay, hit)
                       : triangleSurface<kF>(scene, inst, blas, hit);
    s.frontFace = dot(worldRay.direction, s.geometricNormal) < 0.0f;
    s.instance = hit.instance;
    s.primitive = hit.primitive;
    return s;
}

// Object-space tangent along increasing U and the handedness w (bitangent = cross(n, t) w
// points to decreasing V, "up" in the image, as glTF's normal textures expect). From the
// file's TANGENT where the mesh has one, else from the triangle's UV derivatives; spheres
// use the direction of increasing longitude. False when there is no frame (no UVs, a
// degenerate UV mapping, or a sphere's pole).
PT_HD bool objectTangent(const RenderScene& scene, const SurfaceHit& s, const Hit& hit, Vec3& tangent,
                         float& w) {
    const RenderInstance& inst = scene.instances[s.instance];
    const BlasRef& blas = scene.blases[inst.blas];
    if (blas.kind == GeometryKind::Spheres) {
        const Vec4 sphere = scene.spheres[blas.primitiveOffset + s.primitive];
        const Vec3 radial = objectSpacePoint(inst, s.position) - sphere.xyz();
        tangent = {radial.z, 0.0f, -radial.x};
        w = 1.0f;
        return lengthSquared(tangent) > 0.0f;
    }
    if (!blas.hasUvs) return false;
    const TriangleIndices t = scene.triangles[blas.primitiveOffset + s.primitive];
    if (scene.tangents.count > 0) {
        const Vec4 t0 = scene.tangents[t.v0], t1 = scene.tangents[t.v1], t2 = scene.tangents[t.v2];
        if (t0.w != 0.0f && t1.w != 0.0f && t2.w != 0.0f) {
            const float b0 = 1.0f - hit.u - hit.v;
            tangent = t0.xyz() * b0 + t1.xyz() * hit.u + t2.xyz() * hit.v;
            w = t0.w * b0 + t1.w * hit.u + t2.w * hit.v < 0.0f ? -1.0f : 1.0f;
            return lengthSquared(tangent) > 0.0f;
        }
    }
    const Vec3 p0 = scene.positions[t.v0];
    const Vec3 dp1 = scene.positions[t.v1] - p0, dp2 = scene.positions[t.v2] - p0;
    const Vec2 uv0 = scene.uvs[t.v0];
    const Vec2 duv1 = scene.uvs[t.v1] - uv0, duv2 = scene.uvs[t.v2] - uv0;
    const float det = duv1.x * duv2.y - duv2.x * duv1.y;
    if (!(fabsf(det) > 0.0f)) return false;
    const float inv = 1.0f / det;
    tangent = (dp1 * duv2.y - dp2 * duv1.y) * inv;
    const Vec3 dpdv = (dp2 * duv1.x - dp1 * duv2.x) * inv;
    w = dot(cross(cross(dp1, dp2), tangent), dpdv) < 0.0f ? 1.0f : -1.0f;
    return isFinite(tangent) && lengthSquared(tangent) > 0.0f;
}

// The tangent space at the hit in world space, orthogonal to the shading normal: the frame that
// normal maps and the anisotropy direction (anisotropy_frame.h) are given in. False where there
// is none (objectTangent).
PT_HD bool worldTangentFrame(const RenderScene& scene, const Hit& hit, const SurfaceHit& s, Vec3& t,
                             Vec3& b) {
    Vec3 tangentObject;
    float w;
    if (!objectTangent(scene, s, hit, tangentObject, w)) return false;
    const RenderInstance& inst = scene.instances[s.instance];
    const Vec3 n = s.shadingNormal;
    t = inst.objectToWorld.transformVector(tangentObject);
    t = t - n * dot(n, t);
    if (!(lengthSquared(t) > 0.0f)) return false;
    t = normalize(t);
    // cross(n, t) of the world vectors reverses under a mirroring transform.
    b = cross(n, t) * (inst.flipsWinding ? -w : w);
    return true;
}

// Tangent-space normal mapping (glTF normalTexture, scaled in X and Y by normalScale). The
// result stays on the front side of the geometry, like interpolated vertex normals.
template <FeatureSet kF = kAllFeatures>
PT_HD void applyNormalMap(const RenderScene& scene, const Hit& hit, SurfaceHit& s) {
    if (!hasFeature<kF>(feature::kNormalMap)) return;
    const Material& m = scene.materials[s.material];
    if (!m.normalTexture.present()) return;
    const Vec3 n = s.shadingNormal;
    Vec3 t, b;
    if (!worldTangentFrame(scene, hit, s, t, b)) return;
    const Vec3 texel = sampleTexture(scene, m.normalTexture, s.uv, false).xyz() * 2.0f - Vec3(1.0f);
    const Vec3 mapped = t * (texel.x * m.normalScale) + b * (texel.y * m.normalScale) + n * texel.z;
    if (!(lengthSquared(mapped) > 0.0f) || !isFinite(mapped)) return;
    const Vec3 ns = normalize(mapped);
    s.shadingNormal = dot(ns, s.geometricNormal) > 0.0f ? ns : s.geometricNormal;
}

}  // namespace pt
