// The CUDA backend's edits cost what they change, and still give what a fresh build gives:
// partial vertex uploads, a GPU rebuild that moves the other BLASes' nodes, the light table
// after a transform of lights, and device memory by buffer with what a scene does not use
// left out. Every test skips with a message where no CUDA device is present.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "backend_hit_checks.h"
#include "cuda_test_support.h"
#include "render/backend/cpu/cpu_backend.h"
#include "render/backend/cuda/cuda_backend.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

// Two grids side by side (meshes 0 and 1), one instance each, under a sky.
Scene twoGridScene(uint32_t n) {
    Scene scene;
    scene.render = {48, 48, 4, 16, 0};
    scene.camera.position = {0.0f, 4.0f, 3.0f};
    scene.camera.lookAt = {0, 0, 0};
    scene.environment.color = {1, 1, 1};
    const uint32_t grey = test::addMaterial(scene, "grey", test::diffuse({0.5f, 0.5f, 0.5f}));
    for (uint32_t m = 0; m < 2; ++m) {
        scene.meshes.push_back(test::bumpyGrid(n, m + 1, m == 0 ? -1.1f : 1.1f));
        Instance inst;
        inst.name = "grid " + std::to_string(m);
        inst.mesh = m;
        inst.materials = {grey};
        scene.instances.push_back(inst);
    }
    return scene;
}

std::vector<Ray> downwardRays(uint32_t count, uint32_t seed) {
    return test::downwardRays(count, seed, {2.2f, 1.0f, 1.2f}, 0.3f);
}

void expectSameHits(Backend& a, Backend& b, const char* what) {
    test::expectSameHits(a, b, downwardRays(50000, 11), what);
}

std::map<std::string, uint64_t> memoryByBuffer(const Backend& backend) {
    std::map<std::string, uint64_t> bytes;
    uint64_t total = 0;
    for (const auto& [name, b] : backend.deviceMemoryByBuffer()) {
        EXPECT_EQ(bytes.count(name), 0u) << "buffer " << name << " listed twice";
        bytes[name] = b;
        total += b;
    }
    EXPECT_EQ(total, backend.deviceMemoryBytes());
    return bytes;
}

TEST(CudaEditCost, AFewMovedVerticesTraceLikeAFreshBuild) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = twoGridScene(150);
    cuda::CudaBackend edited;
    IntegratorToggles neverRebuild;
    neverRebuild.rebuildSahRatio = 1e9f;
    edited.setToggles(neverRebuild);
    edited.sync(scene, SceneChanges::All, {});
    // A brush stroke: a few vertices in the middle of the second mesh rise.
    std::vector<Vec3>& p = scene.meshes[1].positions;
    for (size_t i = p.size() / 2; i < p.size() / 2 + 40; ++i) p[i].y += 0.3f;
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "refit");
    cuda::CudaBackend fresh;
    fresh.sync(scene, SceneChanges::All, {});
    expectSameHits(fresh, edited, "partial vertex edit vs fresh build");
    // Moving them back restores the first scene, through the same partial upload.
    for (size_t i = p.size() / 2; i < p.size() / 2 + 40; ++i) p[i].y -= 0.3f;
    edited.sync(scene, SceneChanges::Geometry, {});
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    expectSameHits(cpu, edited, "vertices moved back vs CPU");
}

// The first GPU rebuild of mesh 0 gives it room for an LBVH, which moves mesh 1's nodes.
TEST(CudaEditCost, ARebuildOfOneMeshKeepsTheOthersIntact) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = twoGridScene(80);
    const CompiledScene host = compileRenderScene(scene);
    ASSERT_LT(host.blases[0].nodeCount, cuda::lbvhNodeCount(host.blases[0].primitiveCount))
        << "the CPU build must be smaller than an LBVH for the rebuild to need room";
    cuda::CudaBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    const uint64_t nodesBefore = memoryByBuffer(backend).at("BLAS nodes");
    std::mt19937 rng(5);
    std::shuffle(scene.meshes[0].positions.begin(), scene.meshes[0].positions.end(), rng);
    EXPECT_EQ(backend.sync(scene, SceneChanges::Geometry, {}).action, "rebuild");
    EXPECT_GT(memoryByBuffer(backend).at("BLAS nodes"), nodesBefore)
        << "room for the LBVH came with the rebuild";
    CpuBackend cpu;
    cpu.sync(scene, SceneChanges::All, {});
    expectSameHits(cpu, backend, "after a rebuild of mesh 0");
    // Mesh 1 refits in its new place.
    for (Vec3& v : scene.meshes[1].positions) v.y += 0.1f;
    EXPECT_EQ(backend.sync(scene, SceneChanges::Geometry, {}).action, "refit");
    cpu.sync(scene, SceneChanges::All, {});
    expectSameHits(cpu, backend, "after a refit of the moved mesh 1");
}

// Moving an object moves its lights: the light table then matches a fresh build's, and the
// image with it.
TEST(CudaEditCost, MovingAnObjectWithItsLightsRendersLikeAFreshBuild) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = twoGridScene(20);
    scene.environment.color = {0.1f, 0.1f, 0.1f};
    Light key;
    key.type = LightType::Directional;
    key.direction = {0.3f, -1.0f, 0.2f};
    key.intensity = 2.0f;
    key.object = 0;
    scene.lights.push_back(key);
    SceneObject object;
    object.name = "file";
    scene.objects.push_back(object);
    scene.instances[1].object = 0;
    // One schedule for both (the auto schedule may pick either): the same samples.
    IntegratorToggles fixed;
    fixed.autoSchedule = false;
    cuda::CudaBackend edited;
    edited.setToggles(fixed);
    edited.sync(scene, SceneChanges::All, {});
    scene.instances[1].objectToWorld = translationTransform({0.0f, 0.0f, 3.0f});
    scene.lights[0].direction = {-0.3f, -1.0f, 0.2f};
    const SyncReport report = edited.sync(scene, SceneChanges::Transforms | SceneChanges::Lights, {});
    EXPECT_EQ(report.action, "refit")
        << "the grids are merged: the moved one's copies follow, the merged BLAS is refitted";
    edited.render(16);
    cuda::CudaBackend fresh;
    fresh.setToggles(fixed);
    fresh.sync(scene, SceneChanges::All, {});
    fresh.render(16);
    EXPECT_LE(test::largestBeautyDifference(edited, fresh), 1e-6f)
        << "same samples of the same scene and light table";
}

TEST(CudaEditCost, DeviceMemoryByBufferLeavesOutWhatTheSceneDoesNotUse) {
    PT_REQUIRE_CUDA_DEVICE();
    Scene scene = twoGridScene(40);  // no UVs, no textures, no environment image, no lights
    scene.environment.color = {0, 0, 0};
    Material bright = test::diffuse({0, 0, 0});
    bright.emission = {1, 1, 1};
    scene.instances[1].materials = {test::addMaterial(scene, "light", bright)};
    cuda::CudaBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    std::map<std::string, uint64_t> bytes = memoryByBuffer(backend);
    for (const char* used : {"positions", "triangles", "BLAS nodes", "TLAS nodes", "instances", "materials",
                             "emitters", "accumulation (beauty)"}) {
        EXPECT_GT(bytes.at(used), 0u) << used;
    }
    EXPECT_EQ(bytes.at("normals"), 0u) << "the grids have no normals";
    for (const char* unused :
         {"uvs", "tangents", "spheres", "texels (8-bit)", "texels (float)", "environment pdf",
          "environment conditional cdf", "punctual lights", "BLAS parents (refit)"}) {
        EXPECT_EQ(bytes.at(unused), 0u) << unused;
    }
    // The emitters go with the emission; parent links come with a first refit.
    scene.materials[1].params.emission = {0, 0, 0};
    for (Vec3& v : scene.meshes[0].positions) v.y += 0.01f;
    backend.sync(scene, SceneChanges::Materials | SceneChanges::Geometry, {});
    bytes = memoryByBuffer(backend);
    EXPECT_EQ(bytes.at("emitters"), 0u);
    EXPECT_GT(bytes.at("BLAS parents (refit)"), 0u);

    // One instance: no TLAS nodes once the traversal walks a lone BLAS.
    scene.instances.pop_back();
    backend.sync(scene, SceneChanges::Transforms, {});
    bytes = memoryByBuffer(backend);
    if (cuda::skipsTlasForOneInstance()) {
        EXPECT_EQ(bytes.at("TLAS nodes"), 0u);
        EXPECT_GT(bytes.at("TLAS instance indices"), 0u);
    } else {
        EXPECT_GT(bytes.at("TLAS nodes"), 0u);
    }
    std::vector<Hit> hits;
    backend.traceRays(downwardRays(1000, 3), false, 1, &hits);
    EXPECT_TRUE(
        std::any_of(hits.begin(), hits.end(), [](const Hit& h) { return h.valid() && h.instance == 0; }));
}

}  // namespace
}  // namespace pt
