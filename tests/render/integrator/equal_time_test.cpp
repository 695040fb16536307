// Equal-time comparison of the integrator's strategies (DESIGN.md: "comparisons between
// toggles are made at equal time, not equal samples"). On two small scenes, each strategy
// renders for the same time budget and its relMSE against a high-spp reference is printed:
//   mis      NEE + MIS (the default)
//   nee      NEE only (light sampling where NEE applies, BSDF sampling for delta lobes)
//   bsdf     BSDF sampling only
//   mis-rr0  NEE + MIS without Russian roulette
// MIS must be no worse than the better of light-only and BSDF-only sampling by more than
// noise. The scenes are kept small so the whole test runs in about 20 s on two cores.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "render/integrator/path_tracer.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addFloatTexture;
using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::emitter;
using test::trs;

Material glossy(float roughness) {
    Material m;
    m.baseColor = {0.9f, 0.9f, 0.9f};
    m.metallic = 1.0f;
    m.roughness = roughness;
    return m;
}

// Veach's MIS scene in small: glossy plates of four roughnesses reflecting a small bright
// sphere light and a large dim one, over a diffuse floor.
Scene glossyPlates() {
    Scene scene;
    scene.render = {64, 40, 4, 0, 0};
    scene.camera.position = {0, 2.0f, 6.0f};
    scene.camera.lookAt = {0, 0.3f, 0};
    scene.camera.verticalFovDegrees = 38;
    addShape(scene, ObjectKind::Quad, trs({0, -0.6f, 0}, {0, 0, 0}, {6, 1, 6}),
             addMaterial(scene, "floor", diffuse(Vec3(0.5f))));
    // Front to back, each plate tilted to mirror the lights towards the camera.
    const float roughness[4] = {0.5f, 0.25f, 0.1f, 0.03f};
    for (int i = 0; i < 4; ++i) {
        const float z = 0.9f - 0.6f * i, tilt = 7.0f + 4.0f * i;
        addShape(scene, ObjectKind::Quad, trs({0, -0.45f + 0.25f * i, z}, {tilt, 0, 0}, {1.6f, 1, 0.24f}),
                 addMaterial(scene, "plate" + std::to_string(i), glossy(roughness[i])));
    }
    addShape(scene, ObjectKind::Sphere, trs({-1.0f, 2.2f, -2.5f}, {0, 0, 0}, Vec3(0.04f)),
             addMaterial(scene, "small", emitter(Vec3(2000.0f))));
    addShape(scene, ObjectKind::Sphere, trs({1.2f, 2.2f, -2.5f}, {0, 0, 0}, Vec3(0.6f)),
             addMaterial(scene, "large", emitter(Vec3(4.0f))));
    return scene;
}

// Objects under a sky image with a small bright sun: environment importance sampling, a
// glossy sphere and diffuse interreflection.
Scene sunnyCourtyard() {
    Scene scene;
    scene.render = {64, 40, 6, 0, 0};
    scene.camera.position = {0.5f, 1.4f, 4.0f};
    scene.camera.lookAt = {0, 0.4f, 0};
    scene.camera.verticalFovDegrees = 45;
    scene.environment.texture = addFloatTexture(scene, 64, 32, [](uint32_t x, uint32_t y) {
        const float sky = y < 16 ? 0.3f + 0.02f * float(y) : 0.1f;
        const float sun = (x == 20 || x == 21) && y == 6 ? 4000.0f : 0.0f;
        return Vec4{sky + sun, sky + 0.95f * sun, sky * 1.3f + 0.85f * sun, 1};
    });
    const uint32_t white = addMaterial(scene, "white", diffuse(Vec3(0.7f)));
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}, {0, 0, 0}, {4, 1, 4}), white);
    addShape(scene, ObjectKind::Box, trs({0.9f, 0.5f, -0.6f}, {0, 25, 0}, Vec3(0.5f)), white);
    addShape(scene, ObjectKind::Sphere, trs({-0.6f, 0.5f, 0.2f}, {0, 0, 0}, Vec3(0.5f)),
             addMaterial(scene, "metal", glossy(0.25f)));
    addShape(scene, ObjectKind::Box, trs({-1.6f, 1.0f, -1.4f}, {0, 0, 0}, {0.3f, 1.0f, 0.3f}), white);
    return scene;
}

struct Render {
    std::vector<float> rgba;
    uint32_t spp = 0;
    double seconds = 0.0;
};

// Renders until `seconds` of render time have passed (in small batches).
Render renderFor(const Scene& scene, const IntegratorToggles& toggles, double seconds, uint32_t seed) {
    Scene seeded = scene;
    seeded.render.seed = seed;
    CpuBackend backend;
    backend.setToggles(toggles);
    backend.sync(seeded, SceneChanges::All, {});
    while (backend.stats().renderSeconds < seconds) backend.render(2);
    EXPECT_EQ(backend.stats().nonfiniteSamples, 0u);
    Render r;
    backend.readBeauty(r.rgba);
    r.spp = backend.stats().samplesPerPixel;
    r.seconds = backend.stats().renderSeconds;
    return r;
}

// Relative MSE over pixels and channels: (x - ref)^2 / (ref^2 + 0.01).
double relMse(const std::vector<float>& image, const std::vector<float>& reference) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < image.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = double(image[i]) - reference[i];
        sum += d * d / (double(reference[i]) * reference[i] + 0.01);
        ++n;
    }
    return sum / double(n);
}

void compareAtEqualTime(const char* name, const Scene& scene, double referenceSeconds, double budget) {
    const IntegratorToggles mis{true, true, true, false}, nee{true, false, true, false},
        bsdf{false, false, true, false}, misNoRr{true, true, false, false};
    const Render reference = renderFor(scene, mis, referenceSeconds, 1000);
    struct Entry {
        const char* label;
        IntegratorToggles toggles;
        Render render;
        double error = 0.0;
    } entries[] = {{"mis", mis, {}}, {"nee", nee, {}}, {"bsdf", bsdf, {}}, {"mis-rr0", misNoRr, {}}};
    std::printf("[ equal time ] %s: %ux%u, reference %u spp in %.1f s, budget %.2f s per strategy\n", name,
                scene.render.width, scene.render.height, reference.spp, reference.seconds, budget);
    for (Entry& e : entries) {
        e.render = renderFor(scene, e.toggles, budget, 1);
        e.error = relMse(e.render.rgba, reference.rgba);
        std::printf("[ equal time ] %-10s relMSE %.5f  (%u spp in %.2f s)\n", e.label, e.error, e.render.spp,
                    e.render.seconds);
    }
    std::fflush(stdout);
    const double better = std::min(entries[1].error, entries[2].error);
    EXPECT_LT(entries[0].error, 1.5 * better)
        << name << ": MIS " << entries[0].error << " against the better of "
        << "NEE " << entries[1].error << " and BSDF " << entries[2].error;
}

TEST(EqualTime, GlossyPlatesUnderASmallAndALargeLight) {
    compareAtEqualTime("glossy plates", glossyPlates(), 8.0, 0.8);
}

TEST(EqualTime, SunnyCourtyardUnderASkyImage) {
    compareAtEqualTime("sunny courtyard", sunnyCourtyard(), 8.0, 0.8);
}

}  // namespace
}  // namespace pt
