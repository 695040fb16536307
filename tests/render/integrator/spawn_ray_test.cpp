// Rays leaving a surface (render/integrator/spawn_ray.h, offsetRayOrigin in render/math/ray.h)
// never meet that surface again, wherever it is and however it is scaled, and they leave it by
// a few ulps of its coordinates, not by a fixed epsilon; shadow rays reach a light that hangs a
// ulp under a ceiling; a closed box lets no light in at any scale or distance from the origin.
#include "render/integrator/spawn_ray.h"

#include <gtest/gtest.h>

#include <cmath>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/traversal.h"
#include "render/compile/compile_scene.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

// test::Rng with the directions and transforms these tests draw.
class Random : public test::Rng {
public:
    using test::Rng::Rng;
    // A direction on `normal`'s side, at least `minCos` off the plane.
    Vec3 hemisphere(Vec3 normal, float minCos) {
        for (;;) {
            const Vec3 w = unitVector();
            if (dot(w, normal) >= minCos) return w;
        }
    }
    // Instance transforms from the unit box to 1e5 away and from 1e-4 to 1e3 in size, rotated,
    // non-uniformly scaled and mirrored in turn; never smaller than 1e-4 of their distance from
    // the origin (about a thousand ulps there: a shape of a few ulps has no inside to speak of).
    ObjectTransform transform(int i) {
        const float reach = i % 4 == 0 ? 0.0f : std::pow(10.0f, uniform(0.0f, 5.0f));
        const float magnitude = std::max(std::pow(10.0f, uniform(-4.0f, 3.0f)), 1e-4f * reach);
        Vec3 scale =
            i % 3 == 0 ? Vec3(magnitude) : Vec3{magnitude, magnitude * uniform(0.3f, 3.0f), magnitude};
        if (i % 5 == 0) scale.x = -scale.x;
        const Vec3 translate = inBox(Vec3(-1.0f), Vec3(1.0f)) * reach;
        // Every seventh is axis-aligned and at the origin, where a quad's plane and its hit
        // points are exact (the shape of many a floor).
        if (i % 7 == 0) return test::trs(Vec3(0.0f), Vec3(0.0f), scale);
        return test::trs(translate, inBox(Vec3(0.0f), Vec3(360.0f)), scale);
    }
};

// A scene of one built-in shape under `transform`, compiled.
CompiledScene oneShape(ObjectKind kind, const ObjectTransform& transform) {
    Scene scene;
    test::addShape(scene, kind, transform, test::addMaterial(scene, "white", test::diffuse(Vec3(0.5f))));
    return compileRenderScene(scene);
}

// Where a ray from a random point around the shape, aimed at a random point of it, hits it.
bool hitShape(const RenderScene& scene, Random& random, float size, Vec3 center, SurfaceHit& surface) {
    Ray ray;
    ray.origin = center + random.unitVector() * (3.0f * size);
    ray.direction = normalize(center + random.unitVector() * (0.9f * size * random.uniform()) - ray.origin);
    Hit hit;
    if (!intersectClosest(scene, ray, hit)) return false;
    surface = surfaceAt(scene, ray, hit);
    return true;
}

// Self-intersection: from a hit on a quad (two coplanar triangles) no ray leaving either side
// may meet it again, grazing ones included; the offset is a few ulps of the coordinates (those
// of the translation or of the quad's own size, whichever is larger).
TEST(SpawnRay, RaysLeavingAQuadNeverMeetItAgain) {
    Random random(11);
    int rays = 0, rehits = 0;
    float worstOffsetUlps = 0.0f, worstFarOffsetUlps = 0.0f;
    for (int i = 0; i < 300; ++i) {
        const ObjectTransform transform = random.transform(i);
        const CompiledScene compiled = oneShape(ObjectKind::Quad, transform);
        const RenderScene scene = compiled.view();
        const float size = std::fabs(transform.scale.x) + transform.scale.z;
        for (int h = 0; h < 20; ++h) {
            SurfaceHit surface;
            if (!hitShape(scene, random, size, transform.translate, surface)) continue;
            for (const bool towards : {true, false}) {
                const Vec3 side = towards ? surface.geometricNormal : -surface.geometricNormal;
                const Vec3 origin = spawnOrigin(surface, surface.geometricNormal, towards);
                const float reach = maxComponent(vabs(transform.translate));
                const float ulps = length(origin - surface.position) / (std::max(reach, size) * 0x1p-23f);
                worstOffsetUlps = std::max(worstOffsetUlps, ulps);
                if (reach > 1e3f * size) worstFarOffsetUlps = std::max(worstFarOffsetUlps, ulps);
                for (int d = 0; d < 16; ++d) {
                    Hit hit;
                    ++rays;
                    if (intersectClosest(scene, {origin, random.hemisphere(side, d < 4 ? 1e-3f : 0.0f), kInf},
                                         hit)) {
                        ++rehits;
                    }
                }
            }
        }
    }
    EXPECT_GT(rays, 100000);
    EXPECT_EQ(rehits, 0) << "of " << rays;
    // Far from the origin a couple of ulps of the position, never hundreds (the 256 of Waechter
    // and Binder's constants moved a box 1e5 from the origin by 2 units); near it, the bound on
    // rounding relative to the quad's size (kSpawnRoundings) is what sets the offset.
    EXPECT_LT(worstFarOffsetUlps, 4.0f);
    EXPECT_LT(worstOffsetUlps, 160.0f);
}

// The same for spheres: leaving outwards misses it, leaving inwards crosses it to the far side.
TEST(SpawnRay, RaysLeavingASphereMissItOrCrossIt) {
    Random random(12);
    int rays = 0, failures = 0;
    for (int i = 0; i < 300; ++i) {
        ObjectTransform transform = random.transform(i);
        transform.scale = Vec3(std::fabs(transform.scale.x));  // a sphere in world space
        const CompiledScene compiled = oneShape(ObjectKind::Sphere, transform);
        const RenderScene scene = compiled.view();
        const float radius = transform.scale.x;
        for (int h = 0; h < 20; ++h) {
            SurfaceHit surface;
            if (!hitShape(scene, random, radius, transform.translate, surface)) continue;
            const Vec3 n = surface.geometricNormal;
            for (int d = 0; d < 16; ++d) {
                Hit hit;
                rays += 2;
                const Ray out{spawnOrigin(surface, n, true), random.hemisphere(n, 1e-3f), kInf};
                failures += intersectClosest(scene, out, hit) ? 1 : 0;
                const Vec3 w = random.hemisphere(-n, 0.1f);
                const Ray in{spawnOrigin(surface, n, false), w, kInf};
                const float chord = 2.0f * radius * dot(w, -n);
                failures += intersectClosest(scene, in, hit) && hit.t > 0.5f * chord ? 0 : 1;
            }
        }
    }
    EXPECT_GT(rays, 100000);
    EXPECT_EQ(failures, 0) << "of " << rays;
}

// The Cornell box's ceiling and light 1e5 from the origin: the light hangs 0.005 under the
// ceiling, rounded there to one ulp (1/128). Shadow rays from the floor to points of the light
// must reach it: neither the light itself nor the ceiling right behind it may block them.
// Rays leaving the ceiling beside the light may meet its back (the top), never its emitting face.
TEST(SpawnRay, ShadowRaysReachALightOneUlpUnderTheCeiling) {
    for (const float offset : {0.0f, 1e3f, 1e5f}) {
        Scene box;
        const uint32_t white = test::addMaterial(box, "white", test::diffuse(Vec3(0.7f)));
        Material lamp = test::emitter({4, 4, 4});
        const uint32_t light = test::addMaterial(box, "light", lamp);
        const Vec3 o(offset);
        const uint32_t floor = test::addShape(box, ObjectKind::Quad, test::trs(o + Vec3{0, -1, 0}), white);
        const uint32_t ceiling =
            test::addShape(box, ObjectKind::Quad, test::trs(o + Vec3{0, 1, 0}, {180, 0, 0}), white);
        const uint32_t lightQuad = test::addShape(
            box, ObjectKind::Quad, test::trs(o + Vec3{0, 0.995f, 0}, {180, 0, 0}, {0.5f, 1, 0.4f}), light);
        const CompiledScene compiled = compileRenderScene(box);
        const RenderScene scene = compiled.view();
        Random random(13);
        int shadowRays = 0, blocked = 0, ceilingRays = 0, lightFronts = 0;
        for (int i = 0; i < 20000; ++i) {
            // A floor point, as a ray from above finds it.
            const Vec3 target = o + Vec3{random.uniform(-0.9f, 0.9f), -1.0f, random.uniform(-0.9f, 0.9f)};
            Hit hit;
            const Ray down{o + Vec3{0, 0.5f, 0}, normalize(target - (o + Vec3{0, 0.5f, 0})), kInf};
            ASSERT_TRUE(intersectClosest(scene, down, hit));
            ASSERT_EQ(hit.instance, floor);
            const SurfaceHit surface = surfaceAt(scene, down, hit);
            LightSample sample;
            if (sampleLight(scene, surface.position, random.uniform(), {random.uniform(), random.uniform()},
                            sample)) {
                ++shadowRays;
                blocked += intersectAny(scene, shadowRayTo(surface, sample)) ? 1 : 0;
            }
            // A ceiling point at least 0.02 beside the light, and a ray leaving it downwards.
            const Vec3 beside{random.uniform(0.52f, 1.0f) * (i % 2 ? 1.0f : -1.0f), 1.0f,
                              random.uniform(-1, 1)};
            const Ray up{o + Vec3{0, -0.5f, 0}, normalize(o + beside - (o + Vec3{0, -0.5f, 0})), kInf};
            if (!intersectClosest(scene, up, hit) || hit.instance != ceiling) continue;
            const SurfaceHit onCeiling = surfaceAt(scene, up, hit);
            const Vec3 n = onCeiling.geometricNormal;
            ++ceilingRays;
            const Ray leaving{spawnOrigin(onCeiling, n, true), random.hemisphere(n, 0.0f), kInf};
            if (intersectClosest(scene, leaving, hit) && hit.instance == lightQuad) {
                lightFronts += surfaceAt(scene, leaving, hit).frontFace ? 1 : 0;
            }
        }
        EXPECT_GT(shadowRays, 19000) << offset;
        EXPECT_EQ(blocked, 0) << "offset " << offset << ": of " << shadowRays;
        EXPECT_GT(ceilingRays, 10000) << offset;
        EXPECT_EQ(lightFronts, 0) << "offset " << offset << ": of " << ceilingRays;
    }
}

// A closed box with nothing alight inside, under a bright sky, far from the origin, tiny and
// huge: any ray that slips out through a wall, an edge or a corner brings the sky in. Every
// pixel must be exactly black. (Offsets of 2 units at 1e5 lit it; so did hits that rounded
// onto the plane of the wall meeting their quad's edge.) What no renderer in float can do is
// left out: the walls' translations are floats where they are, so that the walls still meet (a
// box of side 0.2 at 1e5 has its walls rounded 0.0016 apart, a crack in the scene itself), and
// the box inside stands well clear of the floor (a face within an ulp of the floor leaves no
// float between them for a ray to start from).
TEST(SpawnRay, AClosedBoxLetsNoLightInAnywhere) {
    const std::pair<float, float> placements[] = {
        {0.0f, 1.0f}, {1e5f, 1.0f}, {0.0f, 1e-4f}, {-3e4f, 50.0f}, {1e5f, 0.125f}};
    for (const auto& [offset, scale] : placements) {
        Scene scene;
        scene.environment.color = {1, 1, 1};
        scene.render = {24, 24, 6, 0, 0};
        const uint32_t white = test::addMaterial(scene, "white", test::diffuse(Vec3(0.9f)));
        const Vec3 o(offset);
        // An init-capture: C++17 lambdas cannot capture a structured binding (clang refuses).
        const auto at = [&o, scale = scale](Vec3 p) { return o + p * scale; };
        const Vec3 s(scale);
        test::addShape(scene, ObjectKind::Quad, test::trs(at({0, -1, 0}), {0, 0, 0}, s), white);
        test::addShape(scene, ObjectKind::Quad, test::trs(at({0, 1, 0}), {180, 0, 0}, s), white);
        test::addShape(scene, ObjectKind::Quad, test::trs(at({0, 0, -1}), {90, 0, 0}, s), white);
        test::addShape(scene, ObjectKind::Quad, test::trs(at({0, 0, 1}), {-90, 0, 0}, s), white);
        test::addShape(scene, ObjectKind::Quad, test::trs(at({-1, 0, 0}), {0, 0, -90}, s), white);
        test::addShape(scene, ObjectKind::Quad, test::trs(at({1, 0, 0}), {0, 0, 90}, s), white);
        test::addShape(scene, ObjectKind::Box, test::trs(at({0.3f, -0.4f, -0.2f}), {0, 30, 0}, s * 0.3f),
                       white);
        scene.camera.position = at({-0.2f, 0.1f, 0.8f});
        scene.camera.lookAt = at({0.4f, -0.3f, -1.0f});
        scene.camera.verticalFovDegrees = 100;
        const std::vector<float> image = test::renderCpu(scene, 16, {true, true, false});
        double sum = 0.0;
        for (size_t i = 0; i < image.size(); i += 4) sum += image[i] + image[i + 1] + image[i + 2];
        EXPECT_EQ(sum, 0.0) << "offset " << offset << " scale " << scale;
    }
}

}  // namespace
}  // namespace pt
