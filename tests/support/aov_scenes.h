#pragma once
// Scenes whose AOVs are known, shared by the AOV tests of the CPU and CUDA backends: one sphere
// seen by a pinhole camera (analytic hits per pixel centre), and a noisy scene for variance.
#include <cmath>
#include <cstdint>

#include "render/integrator/camera.h"
#include "support/scene_builder.h"

namespace pt::test {

constexpr Vec3 kAovSphereCentre{0.3f, -0.2f, -1.0f};
constexpr float kAovSphereRadius = 1.5f;

// A material with every AOV-visible parameter away from its default.
inline Material aovSphereMaterial() {
    Material m = diffuse({0.25f, 0.5f, 0.75f});
    m.roughness = 0.3f;
    m.metallic = 0.2f;
    m.emission = {0.1f, 0.2f, 0.3f};
    m.emissionStrength = 2.0f;
    return m;
}

// The sphere (instance 0, material 0) under a grey sky, filling about half of the image.
inline Scene analyticSphereScene(uint32_t width = 40, uint32_t height = 32) {
    Scene scene;
    scene.render = {width, height, 4, 4, 0};
    scene.environment.color = {0.5f, 0.5f, 0.5f};
    scene.camera.position = {0.0f, 0.5f, 4.0f};
    scene.camera.lookAt = kAovSphereCentre;
    scene.camera.verticalFovDegrees = 40.0f;
    const uint32_t material = addMaterial(scene, "sphere", aovSphereMaterial());
    const float r = kAovSphereRadius;
    addShape(scene, ObjectKind::Sphere, trs(kAovSphereCentre, {0, 0, 0}, {r, r, r}), material, "sphere");
    return scene;
}

// Where the camera ray through the centre of pixel (x, y) meets the sphere, in double
// precision. `graze`: the ray passes so close to the silhouette that float rounding may decide.
struct AnalyticSphereHit {
    bool hit = false;
    bool graze = false;
    double t = 0.0;    // distance from the camera (unit direction)
    double p[3] = {};  // world position
    double n[3] = {};  // outward unit normal
};

inline AnalyticSphereHit analyticSphereHit(const Scene& scene, uint32_t x, uint32_t y) {
    const uint32_t w = scene.render.width, h = scene.render.height;
    const Ray ray =
        generateCameraRay(makeRenderCamera(scene.camera, w, h), w, h, x, y, {0.5f, 0.5f}, {0.5f, 0.5f});
    double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z},
           d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    const double c[3] = {kAovSphereCentre.x, kAovSphereCentre.y, kAovSphereCentre.z};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double oc[3], b = 0.0, cc = 0.0;
    for (int i = 0; i < 3; ++i) {
        d[i] /= len;
        oc[i] = o[i] - c[i];
        b += oc[i] * d[i];
        cc += oc[i] * oc[i];
    }
    const double r = kAovSphereRadius;
    const double closest = std::sqrt(std::fmax(cc - b * b, 0.0));  // distance of the ray from the centre
    AnalyticSphereHit out;
    out.graze = std::fabs(closest - r) < 1e-3 * r;
    if (closest >= r) return out;
    out.hit = true;
    out.t = -b - std::sqrt(r * r - closest * closest);
    for (int i = 0; i < 3; ++i) {
        out.p[i] = o[i] + d[i] * out.t;
        out.n[i] = (out.p[i] - c[i]) / r;
    }
    return out;
}

// A diffuse sphere on a diffuse floor under a sky: soft shadows and interreflection, so the
// beauty's samples vary from pixel to pixel (variance tests).
inline Scene noisyScene(uint32_t size = 24) {
    Scene scene;
    scene.render = {size, size, 4, 16, 0};
    scene.environment.color = {0.9f, 0.8f, 0.7f};
    scene.camera.position = {0.0f, 1.5f, 4.0f};
    scene.camera.lookAt = {0.0f, 0.3f, 0.0f};
    scene.camera.verticalFovDegrees = 45.0f;
    const uint32_t grey = addMaterial(scene, "grey", diffuse({0.6f, 0.6f, 0.6f}));
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}, {0, 0, 0}, {3, 1, 3}), grey, "floor");
    addShape(scene, ObjectKind::Sphere, trs({0, 0.7f, 0}, {0, 0, 0}, {0.7f, 0.7f, 0.7f}), grey, "ball");
    return scene;
}

}  // namespace pt::test
