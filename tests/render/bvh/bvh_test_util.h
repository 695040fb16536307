#pragma once
// Shared by the BVH tests: random geometry and rays, scene assembly through
// compileRenderScene, and the BVH-versus-brute-force hit comparison.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "render/bvh/aabb.h"
#include "render/bvh/traversal.h"
#include "render/bvh/wide_walk_simd.h"
#include "render/compile/compile_scene.h"
#include "render/scene/scene.h"

namespace pt::test {

class Rng {
public:
    explicit Rng(uint32_t seed) : engine_(seed) {}
    float uniform() { return std::uniform_real_distribution<float>(0.0f, 1.0f)(engine_); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    Vec3 inBox(Vec3 lo, Vec3 hi) { return {uniform(lo.x, hi.x), uniform(lo.y, hi.y), uniform(lo.z, hi.z)}; }
    Vec3 unitVector() {
        const float z = uniform(-1.0f, 1.0f), phi = uniform(0.0f, 2.0f * kPi);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
    uint32_t index(uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(engine_); }

private:
    std::mt19937 engine_;
};

// Triangle soups (unshared vertices) of the shapes that stress builders differently.
enum class SoupKind { Uniform, Clustered, Needles, CoincidentCentroids };
inline const char* soupName(SoupKind kind) {
    switch (kind) {
        case SoupKind::Uniform: return "uniform";
        case SoupKind::Clustered: return "clustered";
        case SoupKind::Needles: return "needles";
        case SoupKind::CoincidentCentroids: return "coincident-centroids";
    }
    return "";
}

// `count` triangles inside roughly [-1, 1]^3.
inline Mesh makeSoup(SoupKind kind, uint32_t count, Rng& rng) {
    Mesh mesh;
    std::vector<Vec3> clusters;
    for (int i = 0; i < 8; ++i) clusters.push_back(rng.inBox(Vec3(-1.0f), Vec3(1.0f)));
    const Vec3 commonCentroid = rng.inBox(Vec3(-0.2f), Vec3(0.2f));
    for (uint32_t i = 0; i < count; ++i) {
        Vec3 p[3];
        if (kind == SoupKind::Uniform) {
            const Vec3 c = rng.inBox(Vec3(-1.0f), Vec3(1.0f));
            for (Vec3& v : p) v = c + rng.inBox(Vec3(-0.05f), Vec3(0.05f));
        } else if (kind == SoupKind::Clustered) {
            const Vec3 c = clusters[rng.index(8)] + rng.unitVector() * (0.05f * rng.uniform());
            for (Vec3& v : p) v = c + rng.inBox(Vec3(-0.01f), Vec3(0.01f));
        } else if (kind == SoupKind::Needles) {
            const Vec3 c = rng.inBox(Vec3(-1.0f), Vec3(1.0f)), axis = rng.unitVector();
            const Vec3 side = rng.unitVector() * 1e-3f;
            p[0] = c - axis;
            p[1] = c + axis;
            p[2] = c + side;
        } else {  // triangles of many sizes and orientations sharing one centroid (almost)
            const float size = 0.01f + rng.uniform();
            const Vec3 a = rng.unitVector() * size, b = rng.unitVector() * size;
            p[0] = commonCentroid + a;
            p[1] = commonCentroid + b;
            p[2] = commonCentroid - a - b;
        }
        for (const Vec3& v : p) {
            mesh.indices.push_back(uint32_t(mesh.positions.size()));
            mesh.positions.push_back(v);
        }
    }
    return mesh;
}

inline std::vector<Aabb> triangleBounds(const Mesh& mesh) {
    std::vector<Aabb> bounds(mesh.indices.size() / 3);
    for (size_t t = 0; t < bounds.size(); ++t) {
        for (int k = 0; k < 3; ++k) bounds[t].grow(mesh.positions[mesh.indices[3 * t + k]]);
    }
    return bounds;
}

inline Mesh makeSphereMesh(const std::vector<Vec4>& spheres) {
    Mesh mesh;
    mesh.kind = GeometryKind::Spheres;
    mesh.spheres = spheres;
    return mesh;
}

// A closed icosphere of radius 1 with shared vertices (consistent winding), `levels` times
// subdivided: 20 * 4^levels triangles.
inline Mesh makeIcosphere(int levels) {
    Mesh mesh;
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    const Vec3 base[12] = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                           {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (const Vec3& v : base) mesh.positions.push_back(normalize(v));
    mesh.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                    4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                    6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            const auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            mesh.positions.push_back(normalize(mesh.positions[a] + mesh.positions[b]));
            return midpoints[key] = uint32_t(mesh.positions.size() - 1);
        };
        std::vector<uint32_t> next;
        for (size_t t = 0; t < mesh.indices.size(); t += 3) {
            const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        mesh.indices = std::move(next);
    }
    return mesh;
}

// The BVH layouts traversal must agree on: the binary tree every backend builds, the CPU's
// 8-wide form of it (render/bvh/wide_bvh.h, IntegratorToggles::wideBvh), walked at the widest
// SIMD level the processor runs (Wide) and at SSE2 (WideSse2; wide_walk_simd.h), and the GPU's
// compressed 8-wide form (render/bvh/compressed_wide_bvh.h), walked here by the same shared code.
enum class Layout { Binary, Wide, WideSse2, Compressed };
constexpr Layout kLayouts[] = {Layout::Binary, Layout::Wide, Layout::WideSse2, Layout::Compressed};
inline const char* layoutName(Layout layout) {
    switch (layout) {
        case Layout::Binary: return "Binary";
        case Layout::Wide: return "Wide";
        case Layout::WideSse2: return "WideSse2";
        case Layout::Compressed: return "Compressed";
    }
    return "";
}
inline CompileOptions layoutOptions(Layout layout, CompileOptions options = {}) {
    options.wideBvh = layout == Layout::Wide || layout == Layout::WideSse2;
    options.compressedWideBvh = layout == Layout::Compressed;
    return options;
}
// For suites of TEST_P over the layouts: the parameter's name in the test's.
inline std::string layoutTestName(const ::testing::TestParamInfo<Layout>& info) {
    return layoutName(info.param);
}

// Base of the suites of TEST_P over the layouts: WideSse2 walks at SSE2 while its test runs.
class LayoutTest : public ::testing::TestWithParam<Layout> {
protected:
    void SetUp() override {
        level_.emplace(GetParam() == Layout::WideSse2 ? SimdLevel::Sse2 : supportedSimdLevel());
    }
    void TearDown() override { level_.reset(); }

private:
    std::optional<ScopedSimdLevel> level_;
};

// A scene with the given meshes and (mesh, transform) instances, compiled with BVHs.
struct InstanceSpec {
    uint32_t mesh;
    Affine3 objectToWorld;
};
inline CompiledScene compileTestScene(std::vector<Mesh> meshes, const std::vector<InstanceSpec>& instances,
                                      const CompileOptions& options = {}) {
    Scene scene;
    scene.meshes = std::move(meshes);
    for (const InstanceSpec& spec : instances) {
        Instance inst;
        inst.mesh = spec.mesh;
        inst.objectToWorld = spec.objectToWorld;
        scene.instances.push_back(inst);
    }
    return compileRenderScene(scene, options);
}
inline CompiledScene compileSingleMesh(Mesh mesh, Layout layout = Layout::Binary) {
    std::vector<Mesh> meshes;
    meshes.push_back(std::move(mesh));
    return compileTestScene(std::move(meshes), {{0, Affine3{}}}, layoutOptions(layout));
}

// A ray from a random point of the box through another: every direction, many misses.
inline Ray randomRay(Rng& rng, Vec3 lo, Vec3 hi) {
    const Vec3 o = rng.inBox(lo, hi);
    return {o, rng.inBox(lo, hi) - o, kInf};
}

// A ray from a random point of the box through a random point of a random triangle of the
// mesh: mostly hits, many of them closest hits behind other triangles.
inline Ray rayAtTriangle(Rng& rng, const Mesh& mesh, Vec3 lo, Vec3 hi) {
    const uint32_t t = rng.index(uint32_t(mesh.indices.size() / 3));
    float a = rng.uniform(), b = rng.uniform();
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    const Vec3 target = mesh.positions[mesh.indices[3 * t]] * (1.0f - a - b) +
                        mesh.positions[mesh.indices[3 * t + 1]] * a +
                        mesh.positions[mesh.indices[3 * t + 2]] * b;
    const Vec3 o = rng.inBox(lo, hi);
    return {o, target - o, kInf};
}

// Closest hit through the BVH equals brute force: same t bit for bit; the same primitive and
// instance unless the BVH's answer ties in t (then brute force must also hit it at that t).
// Returns whether the BVH found a hit. Adds gtest failures; caps the messages per test.
inline bool expectBvhMatchesBruteForce(const RenderScene& bvhScene, const Ray& ray, int& failures) {
    RenderScene bf = bvhScene;
    bf.bruteForce = 1;
    Hit bvhHit, bfHit;
    const bool a = intersectClosest(bvhScene, ray, bvhHit);
    const bool b = intersectClosest(bf, ray, bfHit);
    const bool any = intersectAny(bvhScene, ray);
    bool ok = a == b && any == a;
    // Ties in t go to the lower instance, then the lower primitive, in every walk as in brute
    // force's in-order test (tlas_traversal.h, blas_traversal.h): the same hit, bit for bit.
    if (ok && a) {
        ok = bvhHit.t == bfHit.t && bvhHit.instance == bfHit.instance &&
             bvhHit.primitive == bfHit.primitive && bvhHit.u == bfHit.u && bvhHit.v == bfHit.v;
    }
    if (!ok && ++failures <= 10) {
        ADD_FAILURE() << "ray o=(" << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z << ") d=("
                      << ray.direction.x << "," << ray.direction.y << "," << ray.direction.z << "): bvh " << a
                      << " t=" << bvhHit.t << " prim " << bvhHit.primitive << " inst " << bvhHit.instance
                      << ", brute force " << b << " t=" << bfHit.t << " prim " << bfHit.primitive << " inst "
                      << bfHit.instance << ", any " << any;
    }
    return a;
}

// The work of 2000 closest-hit rays at a 20000-triangle soup, walked as the binary tree
// (first) and as `layout` (second), whose hits must have the same t.
inline std::pair<TraversalStats, TraversalStats> walkWorkAgainstBinary(Layout layout) {
    Rng rng(8);
    const Mesh mesh = makeSoup(SoupKind::Uniform, 20000, rng);
    const CompiledScene binary = compileSingleMesh(mesh, Layout::Binary);
    const CompiledScene other = compileSingleMesh(mesh, layout);
    EXPECT_TRUE(!other.blasWideNodes.empty() || !other.blasCompressedNodes.empty()) << "no wide form";
    TraversalStats binaryStats, otherStats;
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = rayAtTriangle(rng, mesh, Vec3(-1.2f), Vec3(1.2f));
        Hit a, b;
        intersectClosest(binary.view(), ray, a, &binaryStats);
        intersectClosest(other.view(), ray, b, &otherStats);
        EXPECT_EQ(a.t, b.t);
    }
    return {binaryStats, otherStats};
}

}  // namespace pt::test
