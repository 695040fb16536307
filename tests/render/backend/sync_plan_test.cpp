// planSync, the sync plan both backends execute (issue 16), and the CPU backend executing it:
// each kind of edit takes the steps it needs and no more (a material drag builds no BVH), and
// whatever path it takes, the image is the one a fresh compile of the edited scene renders,
// bit for bit at equal samples.
#include "render/backend/sync_plan.h"

#include <gtest/gtest.h>

#include "render/backend/cpu/cpu_backend.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addMaterial;
using test::addShape;
using test::trs;

// A lit room of a few objects: a floor, two spheres, a box, an emissive quad.
Scene room() {
    Scene scene;
    scene.render = {24, 24, 4, 0, 0};
    scene.camera.position = {0, 1, 4};
    scene.camera.lookAt = {0, 0, 0};
    addShape(scene, ObjectKind::Quad, trs({0, -1, 0}, {0, 0, 0}, Vec3(3.0f)),
             addMaterial(scene, "floor", test::diffuse(Vec3(0.6f))), "floor");
    addShape(scene, ObjectKind::Sphere, trs({-0.6f, -0.5f, 0}, {0, 0, 0}, Vec3(0.5f)),
             addMaterial(scene, "red", test::diffuse({0.7f, 0.2f, 0.1f})), "ball");
    addShape(scene, ObjectKind::Box, trs({0.7f, -0.6f, -0.3f}, {0, 30, 0}, Vec3(0.4f)),
             addMaterial(scene, "blue", test::diffuse({0.1f, 0.3f, 0.8f})), "box");
    addShape(scene, ObjectKind::Quad, trs({0, 1.5f, 0}, {180, 0, 0}, Vec3(0.5f)),
             addMaterial(scene, "lamp", test::emitter(Vec3(8.0f))), "lamp");
    scene.environment.color = Vec3(0.05f);
    return scene;
}

TEST(SyncPlan, EachEditTakesItsSteps) {
    const Scene scene = room();
    EXPECT_TRUE(planSync(nullptr, scene, SceneChanges::Camera).fullBuild) << "nothing compiled yet";
    const CompiledScene compiled = compileRenderScene(scene);
    const SyncPlan display = planSync(&compiled, scene, SceneChanges::Display);
    EXPECT_FALSE(display.reset || display.fullBuild || display.materials || display.instances ||
                 display.lights);
    const SyncPlan camera = planSync(&compiled, scene, SceneChanges::Camera);
    EXPECT_TRUE(camera.reset);
    EXPECT_FALSE(camera.fullBuild || camera.materials || camera.instances || camera.lights);
    const SyncPlan material = planSync(&compiled, scene, SceneChanges::Materials);
    EXPECT_TRUE(material.materials && material.reset);
    EXPECT_FALSE(material.fullBuild || material.instances || material.refitGeometry || material.lights);
    const SyncPlan move = planSync(&compiled, scene, SceneChanges::Transforms);
    EXPECT_TRUE(move.instances && !move.fullBuild);
    const SyncPlan vertices = planSync(&compiled, scene, SceneChanges::Geometry);
    EXPECT_TRUE(vertices.refitGeometry && !vertices.fullBuild);
    const SyncPlan sky = planSync(&compiled, scene, SceneChanges::Environment);
    EXPECT_TRUE(sky.lights && sky.environment);
    const SyncPlan lamps = planSync(&compiled, scene, SceneChanges::Lights);
    EXPECT_TRUE(lamps.lights && !lamps.environment);
    for (const SceneChangeMask full :
         {SceneChangeMask(SceneChanges::Topology), SceneChangeMask(SceneChanges::Textures)})
        EXPECT_TRUE(planSync(&compiled, scene, full | SceneChanges::Materials).fullBuild) << full;
}

// The small instances of the room are merged into one BLAS; deleting one changes the merged
// plan, which only a full build can follow.
TEST(SyncPlan, AnInstanceListTheMergedBlasNoLongerHoldsNeedsAFullBuild) {
    Scene scene = room();
    const CompiledScene compiled = compileRenderScene(scene);
    ASSERT_TRUE(compiled.merged.active());
    scene.instances.pop_back();
    scene.objects.pop_back();
    EXPECT_TRUE(planSync(&compiled, scene, SceneChanges::Transforms).fullBuild);
}

TEST(SyncPlan, ActionsRankByCost) {
    SyncActions actions;
    EXPECT_STREQ(syncActionName(actions.most), "nothing");
    for (const SyncAction a :
         {SyncAction::Reset, SyncAction::Tlas, SyncAction::Materials, SyncAction::Lights})
        actions.add(a);
    EXPECT_STREQ(syncActionName(actions.most), "TLAS");
    actions.add(SyncAction::FullBuild);
    EXPECT_STREQ(syncActionName(actions.most), "full build");
}

// Renders `edited` after syncing `changes` into a backend that had compiled `before`, and
// compares with a fresh compile of `edited`.
void expectSyncMatchesAFreshCompile(const Scene& before, const Scene& edited, const SceneDelta& changes,
                                    const char* expectedAction, bool buildsBvh,
                                    const IntegratorToggles& toggles = {}) {
    CpuBackend patched;
    patched.setToggles(toggles);
    patched.sync(before, SceneChanges::All, {});
    patched.render(2);
    const SyncReport report = patched.sync(edited, changes, {});
    EXPECT_EQ(report.action, expectedAction);
    EXPECT_EQ(report.bvhSeconds > 0.0, buildsBvh) << report.bvhSeconds;
    patched.render(8);
    CpuBackend fresh;
    fresh.sync(edited, SceneChanges::All, {});
    fresh.render(8);
    const std::vector<float> a = test::beautyOf(patched), b = test::beautyOf(fresh);
    ASSERT_EQ(a.size(), b.size());
    size_t differing = 0;
    for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
    EXPECT_EQ(differing, 0u) << expectedAction;
}

TEST(CpuSync, AMaterialDragRecompilesMaterialsOnly) {
    const Scene before = room();
    Scene edited = before;
    edited.materials[1].params.roughness = 0.1f;
    edited.materials[1].params.baseColor = {0.2f, 0.8f, 0.2f};
    expectSyncMatchesAFreshCompile(before, edited, SceneChanges::Materials, "materials", false);
    // The editor's drag names its material: only that one is copied.
    expectSyncMatchesAFreshCompile(before, edited, materialsEdited({1}), "materials", false);
}

TEST(CpuSync, EmissionEditsRebuildTheLightTable) {
    const Scene before = room();
    Scene edited = before;
    edited.materials[3].params.emission = Vec3(2.0f, 4.0f, 8.0f);  // the lamp
    edited.materials[2].params.emission = Vec3(1.0f);              // and the box starts to glow
    expectSyncMatchesAFreshCompile(before, edited, SceneChanges::Materials, "materials", false);
    expectSyncMatchesAFreshCompile(before, edited, materialsEdited({2, 3}), "materials", false);
    // Named one at a time (two drags merged by the session), the table still follows both.
    SceneDelta twoDrags = materialsEdited({3});
    twoDrags |= materialsEdited({2});
    expectSyncMatchesAFreshCompile(before, edited, twoDrags, "materials", false);
}

// Only the materials an edit names are copied into the compiled scene; where it names none, or
// the count changed, all of them are, and emission is compared so the light table follows.
TEST(SyncPlan, EditedMaterialsAreCopiedByName) {
    const Scene before = room();
    Scene edited = before;
    edited.materials[0].params.roughness = 0.3f;
    edited.materials[1].params.roughness = 0.7f;
    CompiledScene compiled = compileRenderScene(before);
    MaterialsUpdate update = updateEditedMaterials(edited, compiled, TouchedIds::only({1}));
    EXPECT_FALSE(update.all || update.emissionChanged);
    EXPECT_EQ(update.copied, std::vector<uint32_t>{1});
    EXPECT_EQ(compiled.materials[1].roughness, 0.7f);
    EXPECT_EQ(compiled.materials[0].roughness, before.materials[0].params.roughness) << "not named";
    update = updateEditedMaterials(edited, compiled, TouchedIds{});
    EXPECT_TRUE(update.all);
    EXPECT_EQ(compiled.materials[0].roughness, 0.3f);
    edited.materials[3].params.emission = Vec3(1.0f);  // the lamp dims
    EXPECT_TRUE(updateEditedMaterials(edited, compiled, TouchedIds::only({3})).emissionChanged);
    edited.materials.push_back(edited.materials[0]);
    update = updateEditedMaterials(edited, compiled, TouchedIds::only({0}));
    EXPECT_TRUE(update.all) << "a material more: the count changed";
    EXPECT_EQ(compiled.materials.size(), edited.materials.size() + 1) << "and the fallback";
}

TEST(SyncPlan, TheIdsAnEditNamesReachThePlan) {
    const Scene scene = room();
    const CompiledScene compiled = compileRenderScene(scene);
    SceneDelta delta = materialsEdited({2});
    delta |= meshesMoved({1});
    const SyncPlan plan = planSync(&compiled, scene, delta);
    EXPECT_TRUE(plan.materials && plan.refitGeometry);
    EXPECT_EQ(plan.materialIds, TouchedIds::only({2}));
    EXPECT_EQ(plan.meshes, TouchedIds::only({1}));
    EXPECT_TRUE(planSync(&compiled, scene, SceneChanges::Geometry).meshes.every) << "a bare mask names none";
}

// The first scene instance that is (or is not) in the merged BLAS.
size_t instanceMerged(const Scene& scene, bool merged) {
    const CompiledScene compiled = compileRenderScene(scene);
    size_t i = 0;
    while (i < scene.instances.size() && compiled.merged.sceneInstanceMerged[i] != merged) ++i;
    return i;
}

TEST(CpuSync, AMoveOfAnUnmergedInstanceRebuildsTheTlasOnly) {
    const Scene before = room();
    const size_t ball = instanceMerged(before, false);  // analytic spheres are never merged
    ASSERT_LT(ball, before.instances.size());
    Scene edited = before;
    edited.instances[ball].objectToWorld = trs({-0.4f, -0.4f, 0.2f}, {0, 0, 0}, Vec3(0.5f)).toAffine();
    expectSyncMatchesAFreshCompile(before, edited, SceneChanges::Transforms, "TLAS", true);
}

// A merged instance that moves moves its copy in the merged BLAS, which is refitted.
TEST(CpuSync, AMoveOfAMergedInstanceRefitsTheMergedBlas) {
    const Scene before = room();
    const size_t box = instanceMerged(before, true);
    ASSERT_LT(box, before.instances.size()) << "the room's small meshes are merged";
    Scene edited = before;
    ObjectTransform t = before.objects[size_t(before.instances[box].object)].transform;
    t.translate.x += 0.02f;
    edited.instances[box].objectToWorld = t.toAffine();
    expectSyncMatchesAFreshCompile(before, edited, SceneChanges::Transforms, "refit", true);
    // A refit whose SAH cost drifts past the rebuild ratio (here: any refit) compiles again.
    IntegratorToggles rebuildAlways;
    rebuildAlways.rebuildSahRatio = 1e-3f;
    expectSyncMatchesAFreshCompile(before, edited, SceneChanges::Transforms, "full build", true,
                                   rebuildAlways);
}

// Vertices that move (a morph, a sculpt) refit their mesh's BLAS and, for a merged mesh, the
// merged BLAS's copy.
TEST(CpuSync, MovedVerticesRefitTheirBlases) {
    const Scene before = room();
    Scene edited = before;
    const uint32_t boxMesh = edited.instances[instanceMerged(before, true)].mesh;
    for (Vec3& p : edited.meshes[boxMesh].positions) p = p * 0.8f + Vec3(0.0f, 0.1f * p.x, 0.0f);
    expectSyncMatchesAFreshCompile(before, edited, SceneChanges::Geometry, "refit", true);
    expectSyncMatchesAFreshCompile(before, edited, meshesMoved({boxMesh}), "refit", true);
}

}  // namespace
}  // namespace pt
