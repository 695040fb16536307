#pragma once
// From a Hit to what shading needs: world position, geometric and shading normals, UV and
// material. Positions are interpolated from the primitive, not taken as origin + t * dir,
// so they lie on the surface to float precision however far the ray travelled.
#include "render/bvh/hit.h"
#include "render/lights/emitter_sample.h"
#include "render/math/ray.h"
#include "render/scene/render_scene.h"

namespace pt {

struct SurfaceHit {
    Vec3 position;
    Vec3 geometricNormal;  // unit, on the front side (winding, after the instance transform)
    Vec3 shadingNormal;    // unit, same hemisphere as geometricNormal
    Vec2 uv;
    bool frontFace;        // the ray arrived from the front side
    uint32_t material;     // RenderScene::materials index
    float triangleArea;    // world space; 0 for spheres
    bool isEmitterTriangle;  // part of the NEE emitter table (triangle, emissive)
};

PT_HD SurfaceHit triangleSurface(const RenderScene& scene, const RenderInstance& inst,
                                 const BlasRef& blas, const Hit& hit) {
    SurfaceHit s{};
    const TriangleIndices t = scene.triangles[blas.primitiveOffset + hit.primitive];
    const float b0 = 1.0f - hit.u - hit.v;
    const Vec3 p0 = scene.positions[t.v0], p1 = scene.positions[t.v1], p2 = scene.positions[t.v2];
    s.position = inst.objectToWorld.transformPoint(p0 * b0 + p1 * hit.u + p2 * hit.v);
    const Vec3 nObject = cross(p1 - p0, p2 - p0);
    Vec3 ng = normalize(inst.worldToObject.transformNormalByInverse(nObject));
    if (inst.flipsWinding) ng = -ng;
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
    if (blas.hasUvs) s.uv = scene.uvs[t.v0] * b0 + scene.uvs[t.v1] * hit.u + scene.uvs[t.v2] * hit.v;
    s.material = scene.instanceMaterials[inst.materialOffset + scene.triangleSlots[blas.primitiveOffset + hit.primitive]];
    const Vec3 w0 = inst.objectToWorld.transformPoint(p0);
    s.triangleArea = 0.5f * length(cross(inst.objectToWorld.transformPoint(p1) - w0,
                                          inst.objectToWorld.transformPoint(p2) - w0));
    s.isEmitterTriangle = scene.materials[s.material].isEmissive();
    return s;
}

PT_HD SurfaceHit sphereSurface(const RenderScene& scene, const RenderInstance& inst,
                               const BlasRef& blas, const Ray& worldRay, const Hit& hit) {
    SurfaceHit s{};
    const Vec4 sphere = scene.spheres[blas.primitiveOffset + hit.primitive];
    const Vec3 o = inst.worldToObject.transformPoint(worldRay.origin);
    const Vec3 d = inst.worldToObject.transformVector(worldRay.direction);
    // Project back onto the sphere: removes the error of o + t d.
    const Vec3 radial = normalize(o + d * hit.t - sphere.xyz());
    s.position = inst.objectToWorld.transformPoint(sphere.xyz() + radial * sphere.w);
    s.geometricNormal = normalize(inst.worldToObject.transformNormalByInverse(radial));
    if (inst.flipsWinding) s.geometricNormal = -s.geometricNormal;
    s.shadingNormal = s.geometricNormal;
    // Equirectangular UV about the object's +Y axis.
    s.uv = {0.5f + atan2f(radial.x, radial.z) * (0.5f * kInvPi), acosf(clampf(radial.y, -1.0f, 1.0f)) * kInvPi};
    s.material = scene.instanceMaterials[inst.materialOffset + scene.sphereSlots[blas.primitiveOffset + hit.primitive]];
    return s;
}

PT_HD SurfaceHit surfaceAt(const RenderScene& scene, const Ray& worldRay, const Hit& hit) {
    const RenderInstance& inst = scene.instances[hit.instance];
    const BlasRef& blas = scene.blases[inst.blas];
    SurfaceHit s = blas.kind == GeometryKind::Spheres ? sphereSurface(scene, inst, blas, worldRay, hit)
                                                      : triangleSurface(scene, inst, blas, hit);
    s.frontFace = dot(worldRay.direction, s.geometricNormal) < 0.0f;
    return s;
}

}  // namespace pt
