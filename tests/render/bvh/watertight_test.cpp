// Watertightness: rays aimed exactly at shared edges and vertices never slip through, both for
// the bare triangle test (a closed fan) and through the BVH (rays from inside closed meshes,
// where box tests at node boundaries could also lose a hit).
#include <gtest/gtest.h>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/triangle_intersect.h"
#include "render/scene/builtin_shapes.h"

namespace pt {
namespace {

using test::Rng;

// A closed fan: a centre vertex and a ring of `n` >= 5 vertices at random radii, with heights
// of at most 2% of the radius, randomly rotated and placed. No ring gap exceeds 100 degrees, so
// the fan is a star around its centre, and no triangle tilts more than ~20 degrees; rays come
// within 45 degrees of the fan's axis, so the fan's projection along a ray never folds and
// every ray through a spoke (shared by two triangles) or the centre (shared by all) crosses it.
struct Fan {
    Vec3 center;
    std::vector<Vec3> ring;
    Affine3 frame;  // fan space (axis +z) to world
    Vec3 vertex(int i) const { return ring[size_t(i) % ring.size()]; }
};

Fan makeFan(Rng& rng, int n, float scale, Vec3 offset) {
    Fan fan;
    const Vec3 axis = rng.unitVector();
    const float half = rng.uniform(0.0f, kPi), s = std::sin(half);
    fan.frame = translationTransform(offset) *
                rotationTransform({axis.x * s, axis.y * s, axis.z * s, std::cos(half)}) *
                scaleTransform(Vec3(scale));
    fan.center = fan.frame.transformPoint(rng.inBox({-0.1f, -0.1f, -0.02f}, {0.1f, 0.1f, 0.02f}));
    for (int i = 0; i < n; ++i) {
        const float phi = 2.0f * kPi * (float(i) + rng.uniform(0.3f, 0.7f)) / float(n);
        const float r = rng.uniform(0.5f, 1.0f);
        fan.ring.push_back(
            fan.frame.transformPoint({r * std::cos(phi), r * std::sin(phi), rng.uniform(-0.02f, 0.02f)}));
    }
    return fan;
}

bool fanHit(const Fan& fan, const Ray& ray) {
    for (size_t i = 0; i < fan.ring.size(); ++i) {
        float t, u, v;
        // Alternate windings: two-sided watertightness must not depend on them.
        const bool hit =
            i % 2 ? intersectTriangle(ray, fan.center, fan.vertex(int(i)), fan.vertex(int(i) + 1), t, u, v)
                  : intersectTriangle(ray, fan.vertex(int(i) + 1), fan.vertex(int(i)), fan.center, t, u, v);
        if (hit) return true;
    }
    return false;
}

TEST(Watertight, RaysAtSharedEdgesAndVerticesOfAFanAlwaysHit) {
    Rng rng(17);
    uint64_t rays = 0, slipped = 0;
    for (int f = 0; f < 400; ++f) {
        // Fans far from the origin stay large enough (>= 1e4 ulps) that rounding the targets
        // on the spokes cannot carry them past the fan's outer boundary.
        const bool far = f % 4 == 0;
        const float scale = std::pow(10.0f, far ? rng.uniform(0.0f, 3.0f) : rng.uniform(-3.0f, 3.0f));
        const Vec3 offset = rng.inBox(Vec3(-1.0f), Vec3(1.0f)) * (far ? 1e4f : 1.0f);
        const Fan fan = makeFan(rng, 5 + f % 12, scale, offset);
        for (int r = 0; r < 2500; ++r) {
            const int spoke = int(rng.index(uint32_t(fan.ring.size())));
            Vec3 target;
            switch (r % 3) {
                case 0: target = fan.center; break;
                case 1: target = (fan.center + fan.vertex(spoke)) * 0.5f; break;
                default: target = lerp(fan.center, fan.vertex(spoke), rng.uniform(0.01f, 0.95f)); break;
            }
            // A direction within 45 degrees of the axis, from either side, 0.5 to 20 sizes away.
            Vec3 d = rng.unitVector();
            d.z = std::copysign(std::max(std::fabs(d.z), 0.71f), d.z);
            const Vec3 away = normalize(fan.frame.transformVector(d)) * (scale * rng.uniform(0.5f, 20.0f));
            const Vec3 origin = target + away;
            const Ray ray{origin, target - origin, kInf};
            ++rays;
            if (!fanHit(fan, ray) && ++slipped <= 5) {
                ADD_FAILURE() << "ray slipped through fan " << f << " (target kind " << r % 3 << ", scale "
                              << scale << ")";
            }
        }
    }
    EXPECT_EQ(slipped, 0u) << "of " << rays << " rays";
}

// Rays from random interior points to the mesh's vertices and edge midpoints (in float).
uint64_t shootFromInside(const RenderScene& scene, const Mesh& mesh, Rng& rng, float interiorRadius,
                         Vec3 center, int rays) {
    uint64_t slipped = 0;
    const uint32_t triangles = uint32_t(mesh.indices.size() / 3);
    for (int r = 0; r < rays; ++r) {
        const uint32_t t = rng.index(triangles);
        const Vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]];
        const Vec3 target = r % 2 ? a : (a + b) * 0.5f;
        const Vec3 origin = center + rng.unitVector() * (interiorRadius * rng.uniform());
        Hit hit;
        if (!intersectClosest(scene, Ray{origin, target - origin, kInf}, hit)) ++slipped;
    }
    return slipped;
}

class WatertightLayouts : public test::LayoutTest {};
INSTANTIATE_TEST_SUITE_P(Layouts, WatertightLayouts, ::testing::ValuesIn(test::kLayouts),
                         test::layoutTestName);

TEST_P(WatertightLayouts, RaysFromInsideAClosedIcosphereAlwaysHit) {
    Rng rng(23);
    const Mesh sphere = test::makeIcosphere(4);  // 5120 triangles
    const CompiledScene compiled = test::compileSingleMesh(sphere, GetParam());
    EXPECT_EQ(shootFromInside(compiled.view(), sphere, rng, 0.9f, Vec3(0.0f), 400000), 0u);
}

TEST_P(WatertightLayouts, RaysFromInsideAnInstancedBoxAlwaysHit) {
    Rng rng(29);
    const Mesh box = makeUnitBox();
    // Object space is where the triangle test runs: shoot there through a transformed instance.
    const Affine3 toWorld = translationTransform({3, -2, 1}) *
                            rotationTransform({0.3f, 0.5f, -0.1f, 0.806f}) *
                            scaleTransform({2.0f, 0.5f, -1.5f});
    uint64_t slipped = 0;
    for (const Affine3& transform : {Affine3{}, toWorld}) {
        const CompiledScene compiled =
            test::compileTestScene({box}, {{0, transform}}, test::layoutOptions(GetParam()));
        const RenderScene scene = compiled.view();
        for (int r = 0; r < 100000; ++r) {
            const uint32_t t = rng.index(12);
            const Vec3 a = box.positions[box.indices[3 * t]], b = box.positions[box.indices[3 * t + 1]];
            const Vec3 target = r % 2 ? a : (a + b) * 0.5f;
            // Half the origins at the centre: with the identity transform many directions then
            // have exact zero components.
            const Vec3 local = r % 4 < 2 ? rng.inBox(Vec3(-0.9f), Vec3(0.9f)) : Vec3{0, 0, 0};
            const Ray ray{transform.transformPoint(local), transform.transformVector(target - local), kInf};
            Hit hit;
            if (!intersectClosest(scene, ray, hit)) ++slipped;
        }
    }
    EXPECT_EQ(slipped, 0u);
}

}  // namespace
}  // namespace pt
