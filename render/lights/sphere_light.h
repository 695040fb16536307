#pragma once
// Emissive analytic spheres as lights. NEE samples the cone of directions under which the
// sphere is seen, uniformly, so the density is 1 / (2 pi (1 - cos theta_max)) in solid angle
// (pbrt-v4, SphereLight / Sphere::Sample with a reference point, including its Taylor
// expansion for spheres seen under less than 1.5 degrees). Only spheres of uniformly scaled
// instances are spheres in world space; others (ellipsoids) are left to BSDF sampling.
#include "render/lights/emitter_sample.h"
#include "render/math/frame.h"

namespace pt {

struct WorldSphere {
    Vec3 center;
    float radius;
};

// Equirectangular UV of a unit radial direction in the sphere's object space, about +Y.
PT_HD Vec2 sphereUv(Vec3 radial) {
    return {0.5f + atan2f(radial.x, radial.z) * (0.5f * kInvPi),
            acosf(clampf(radial.y, -1.0f, 1.0f)) * kInvPi};
}

// False when the instance's transform is not a rotation and uniform scale (up to 1e-4).
PT_HD bool worldSphere(const RenderScene& scene, uint32_t instanceIndex, uint32_t primitive,
                       WorldSphere& out) {
    const RenderInstance& inst = scene.instances[instanceIndex];
    const BlasRef& blas = scene.blases[inst.blas];
    const Vec4 s = scene.spheres[blas.primitiveOffset + primitive];
    const Affine3& m = inst.objectToWorld;
    const Vec3 c0{m.rows[0].x, m.rows[1].x, m.rows[2].x};
    const Vec3 c1{m.rows[0].y, m.rows[1].y, m.rows[2].y};
    const Vec3 c2{m.rows[0].z, m.rows[1].z, m.rows[2].z};
    const float l0 = dot(c0, c0), tolerance = 1e-4f * l0;
    if (fabsf(dot(c1, c1) - l0) > tolerance || fabsf(dot(c2, c2) - l0) > tolerance ||
        fabsf(dot(c0, c1)) > tolerance || fabsf(dot(c0, c2)) > tolerance || fabsf(dot(c1, c2)) > tolerance) {
        return false;
    }
    out.center = m.transformPoint(s.xyz());
    out.radius = s.w * sqrtf(l0);
    return out.radius > 0.0f;
}

// Light-table weight: surface area x luminance (power / pi).
PT_HD float sphereLightWeight(const WorldSphere& sphere, const Material& m) {
    return 4.0f * kPi * sphere.radius * sphere.radius * luminance(m.emittedRadiance());
}

// 1 - cos(theta_max) of the cone that a sphere subtends, given sin^2(theta_max); exact for
// small angles, where 1 - sqrt(1 - x) would cancel.
PT_HD float sphereConeOneMinusCos(float sin2ThetaMax) {
    if (sin2ThetaMax < 0.00068523f) return 0.5f * sin2ThetaMax;  // sin^2(1.5 degrees)
    return 1.0f - sqrtf(fmaxf(0.0f, 1.0f - sin2ThetaMax));
}

// Solid-angle density of sampleSphereCone() for any direction that meets the sphere;
// 0 from inside it.
PT_HD float sphereConePdf(const WorldSphere& sphere, Vec3 ref) {
    const float distance2 = lengthSquared(sphere.center - ref);
    const float radius2 = sphere.radius * sphere.radius;
    if (!(distance2 > radius2)) return 0.0f;
    return 1.0f / (2.0f * kPi * sphereConeOneMinusCos(radius2 / distance2));
}

struct SphereConeSample {
    Vec3 wi;      // unit, from ref
    Vec3 point;   // on the visible cap
    Vec3 normal;  // outward
    float distance;
    float pdf;  // solid angle
};

PT_HD bool sampleSphereCone(const WorldSphere& sphere, Vec3 ref, Vec2 u, SphereConeSample& out) {
    const Vec3 toCenter = sphere.center - ref;
    const float distance2 = lengthSquared(toCenter);
    const float radius2 = sphere.radius * sphere.radius;
    if (!(distance2 > radius2)) return false;  // inside: the front (outer) face is not visible
    const float distance = sqrtf(distance2);
    const float sinThetaMax = sphere.radius / distance;
    const float sin2ThetaMax = radius2 / distance2;
    const float oneMinusCosMax = sphereConeOneMinusCos(sin2ThetaMax);
    float cosTheta = 1.0f - oneMinusCosMax * u.x;
    float sin2Theta = 1.0f - cosTheta * cosTheta;
    if (sin2ThetaMax < 0.00068523f) {
        sin2Theta = sin2ThetaMax * u.x;
        cosTheta = sqrtf(1.0f - sin2Theta);
    }
    // Angle at the centre between the direction to ref and the sampled surface point.
    const float cosAlpha =
        sin2Theta / sinThetaMax + cosTheta * sqrtf(fmaxf(0.0f, 1.0f - sin2Theta / sin2ThetaMax));
    const float sinAlpha = sqrtf(fmaxf(0.0f, 1.0f - cosAlpha * cosAlpha));
    const float phi = 2.0f * kPi * u.y;
    const Frame frame = Frame::fromNormal(toCenter / distance);
    out.normal = normalize(frame.toWorld({-sinAlpha * cosf(phi), -sinAlpha * sinf(phi), -cosAlpha}));
    out.point = sphere.center + out.normal * sphere.radius;
    const Vec3 toPoint = out.point - ref;
    out.distance = length(toPoint);
    if (!(out.distance > 0.0f)) return false;
    out.wi = toPoint / out.distance;
    out.pdf = 1.0f / (2.0f * kPi * oneMinusCosMax);
    return true;
}

// Radiance leaving the front of sphere `primitive` of instance `instanceIndex` at world
// `point`, times the surface's alpha coverage there (as NEE sees it; see emitter_sample.h).
template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 sphereEmittedRadiance(const RenderScene& scene, uint32_t instanceIndex, uint32_t primitive,
                                 Vec3 point) {
    const RenderInstance& inst = scene.instances[instanceIndex];
    const BlasRef& blas = scene.blases[inst.blas];
    const Vec4 s = scene.spheres[blas.primitiveOffset + primitive];
    const Material& m = emitterMaterial(scene, instanceIndex, primitive, GeometryKind::Spheres);
    Vec2 uv{0.0f, 0.0f};
    if (hasFeature<kF>(feature::kEmissiveTexture | feature::kTransparency) &&
        (m.emissiveTexture.present() || materialMayBeTransparent(m))) {
        uv = sphereUv(normalize(objectSpacePoint(inst, point) - s.xyz()));
    }
    return emittedRadiance<kF>(scene, m, uv) * surfaceCoverage<kF>(scene, m, uv);
}

}  // namespace pt
