#include "render/compile/compile_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::trs;

// A flat grid of 2 * n * n triangles in the XZ plane.
Mesh gridMesh(uint32_t n) {
    Mesh mesh;
    mesh.name = "grid";
    for (uint32_t z = 0; z <= n; ++z) {
        for (uint32_t x = 0; x <= n; ++x) mesh.positions.push_back({float(x), 0.0f, float(z)});
    }
    for (uint32_t z = 0; z < n; ++z) {
        for (uint32_t x = 0; x < n; ++x) {
            const uint32_t a = z * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
            for (uint32_t index : {a, c, b, b, c, d}) mesh.indices.push_back(index);
        }
    }
    return mesh;
}

Scene sceneWithGrid(uint32_t n, uint32_t instances) {
    Scene scene;
    scene.meshes.push_back(gridMesh(n));
    const uint32_t m = addMaterial(scene, "m", diffuse({0.5f, 0.5f, 0.5f}));
    for (uint32_t i = 0; i < instances; ++i) {
        Instance inst;
        inst.mesh = 0;
        inst.objectToWorld = translationTransform({0.0f, float(i), 0.0f});
        inst.materials.push_back(m);
        scene.instances.push_back(inst);
    }
    return scene;
}

TEST(CompileScene, BvhBuildReportsMonotoneProgressFromZeroToOne) {
    const Scene scene = sceneWithGrid(300, 1);  // 180,000 triangles
    std::vector<double> reports;
    compileRenderScene(scene, {}, [&](const std::string& stage, double fraction) {
        if (stage == "build BVH") reports.push_back(fraction);
    });
    ASSERT_GE(reports.size(), 10u);
    EXPECT_EQ(reports.front(), 0.0);
    EXPECT_EQ(reports.back(), 1.0);
    for (size_t i = 1; i < reports.size(); ++i) EXPECT_LE(reports[i - 1], reports[i]);
}

TEST(CompileScene, OneMeshInstancedManyTimesIsOneBlas) {
    CompileOptions instanced;
    instanced.mergeSmallInstances = false;
    const CompiledScene compiled = compileRenderScene(sceneWithGrid(10, 25), instanced);
    EXPECT_EQ(compiled.stats.blasCount, 1u);
    EXPECT_EQ(compiled.stats.instanceCount, 25u);
    EXPECT_EQ(compiled.stats.meshTriangles, 200u);
    EXPECT_EQ(compiled.stats.instancedTriangles, 25u * 200u);
    EXPECT_EQ(compiled.triangles.size(), 200u);
}

// Merged small instances (render/compile/merged_geometry.h): 25 instances of a 200-triangle
// grid become 5000 world-space copies in one BLAS, which the TLAS holds as its one entry; each
// copy maps back to its instance and triangle. A moved instance's copies follow it, a hidden
// one's collapse to a point.
TEST(CompileScene, SmallInstancesMergeIntoOneWorldSpaceBlas) {
    Scene scene = sceneWithGrid(10, 25);
    CompiledScene compiled = compileRenderScene(scene);
    ASSERT_TRUE(compiled.merged.active());
    EXPECT_EQ(compiled.blases.size(), 2u);
    EXPECT_EQ(compiled.blases[compiled.merged.blas].primitiveCount, 5000u);
    EXPECT_EQ(compiled.instances.size(), 25u) << "instances keep their place for shading";
    EXPECT_EQ(compiled.tlasInstanceIndices, std::vector<uint32_t>{25u});
    ASSERT_EQ(compiled.mergedTriangles.size(), 5000u);
    EXPECT_EQ(compiled.mergedTriangles[200 * 7 + 13].instance, 7u);
    EXPECT_EQ(compiled.mergedTriangles[200 * 7 + 13].primitive, 13u);
    const Mesh& grid = scene.meshes[0];
    const auto copyOf = [&](uint32_t piece, uint32_t vertex) {
        return compiled.positions[compiled.merged.pieces[piece].firstVertex + vertex];
    };
    EXPECT_EQ(copyOf(7, 5).y, grid.positions[5].y + 7.0f);

    scene.instances[7].objectToWorld = translationTransform({3.0f, 0.0f, 0.0f});
    scene.instances[8].visible = false;
    EXPECT_TRUE(compileInstances(scene, compiled)) << "the copies changed";
    EXPECT_EQ(copyOf(7, 5).x, grid.positions[5].x + 3.0f);
    EXPECT_EQ(copyOf(8, 0), copyOf(8, 5)) << "hidden: collapsed to one point";
    EXPECT_EQ(compiled.instances.size(), 24u);
    EXPECT_EQ(compiled.mergedTriangles[200 * 9].instance, 8u) << "indices follow the shorter instance list";
    EXPECT_FALSE(compileInstances(scene, compiled)) << "nothing moved since";

    CompileOptions far;
    scene = sceneWithGrid(10, 25);
    for (Instance& inst : scene.instances)
        inst.objectToWorld = translationTransform({1e5f, 0.0f, 0.0f}) * inst.objectToWorld;
    EXPECT_FALSE(compileRenderScene(scene, far).merged.active())
        << "far from the origin for their size: instanced";
}

TEST(CompileScene, BruteForceIsRefusedAboveItsBudgetWithAClearMessage) {
    CompileOptions options;
    options.bruteForce = true;
    options.bruteForceBudget = 1000;
    EXPECT_NO_THROW(compileRenderScene(sceneWithGrid(10, 5), options));  // exactly 1000
    try {
        compileRenderScene(sceneWithGrid(10, 6), options);
        FAIL() << "expected a refusal";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(
            e.what(),
            "BVH off (brute force) refused: the scene traces 1200 triangles, over the budget of 1000");
    }
}

TEST(CompileScene, BadReferencesAreErrorsNotCrashes) {
    Scene badMesh = sceneWithGrid(2, 1);
    badMesh.instances[0].mesh = 7;
    EXPECT_THROW(compileRenderScene(badMesh), std::invalid_argument);
    Scene badIndex = sceneWithGrid(2, 1);
    badIndex.meshes[0].indices[4] = 999;
    EXPECT_THROW(compileRenderScene(badIndex), std::invalid_argument);
    Scene badMaterial = sceneWithGrid(2, 1);
    badMaterial.instances[0].materials = {42};
    EXPECT_THROW(compileRenderScene(badMaterial), std::invalid_argument);
}

// The compiler checks a mesh's corners and material slots in parallel chunks; like the serial
// loop before it, it names the first bad triangle or primitive, whichever chunk finds one first.
TEST(CompileScene, ABadCornerOrSlotIsNamedByTheFirstTriangleThatHasOne) {
    Scene corners = sceneWithGrid(300, 1);  // 180,000 triangles: several chunks
    const uint32_t vertices = uint32_t(corners.meshes[0].positions.size());
    corners.meshes[0].indices[3 * 170000 + 2] = vertices;  // a late chunk
    corners.meshes[0].indices[3 * 90001 + 1] = vertices + 5;
    try {
        compileRenderScene(corners);
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), ("mesh 0 \"grid\": triangle 90001 indexes past its " +
                                std::to_string(vertices) + " vertices")
                                   .c_str());
    }
    Scene slots = sceneWithGrid(300, 1);
    Mesh& mesh = slots.meshes[0];
    mesh.slotCount = 2;
    mesh.primitiveSlots.assign(mesh.indices.size() / 3, 1u);
    mesh.primitiveSlots[175000] = 7;
    mesh.primitiveSlots[70002] = 2;
    slots.instances[0].materials.push_back(slots.instances[0].materials[0]);
    try {
        compileRenderScene(slots);
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "mesh 0 \"grid\": primitive 70002 uses slot 2 of 2");
    }
    mesh.primitiveSlots[175000] = mesh.primitiveSlots[70002] = 0;
    const CompiledScene compiled = compileRenderScene(slots);
    ASSERT_EQ(compiled.triangleSlots.size(), mesh.primitiveSlots.size());
    EXPECT_EQ(compiled.triangleSlots[70002], 0u);
    EXPECT_EQ(compiled.triangleSlots[70003], 1u);
    // Without a slot list every primitive takes slot 0, which a mesh of no slots lacks: the
    // first primitive is named.
    Scene noSlots = sceneWithGrid(300, 1);
    noSlots.meshes[0].slotCount = 0;
    try {
        compileRenderScene(noSlots);
        FAIL() << "expected an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "mesh 0 \"grid\": primitive 0 uses slot 0 of 0");
    }
}

TEST(CompileScene, EmittersAreWeightedByWorldAreaTimesLuminance) {
    Scene scene;
    Material bright = diffuse({0, 0, 0});
    bright.emission = {1, 1, 1};
    bright.emissionStrength = 4.0f;
    const uint32_t light = addMaterial(scene, "light", bright);
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}), light);                           // area 4
    addShape(scene, ObjectKind::Quad, trs({0, 5, 0}, {0, 0, 0}, {2, 1, 3}), light);     // area 24
    addShape(scene, ObjectKind::Sphere, trs({0, -5, 0}), light);                        // area 4 pi
    addShape(scene, ObjectKind::Sphere, trs({0, -9, 0}, {0, 0, 0}, {1, 2, 1}), light);  // ellipsoid: no NEE
    const CompiledScene compiled = compileRenderScene(scene);
    ASSERT_EQ(compiled.emitters.emitters.size(), 5u);
    EXPECT_EQ(compiled.stats.emitterCount, 4u);
    EXPECT_EQ(compiled.stats.sphereLightCount, 1u);
    EXPECT_NEAR(compiled.emitters.totalWeight, (4.0f + 24.0f + 4.0f * kPi) * 4.0f, 1e-3f);
    EXPECT_NEAR(compiled.emitters.emitters[2].weight, 12.0f * 4.0f, 1e-4f);
    EXPECT_EQ(compiled.emitters.emitters[4].kind, LightKind::Sphere);
}

// Punctual lights by their power / pi, the environment by its flux through the scene's
// bounding sphere (emitter_table.h), all in one table; beside local lights the environment's
// share stays within [1/4, 3/4].
TEST(CompileScene, PunctualLightsAndTheEnvironmentShareTheLightTable) {
    Scene scene;
    addShape(scene, ObjectKind::Box, trs({0, 0, 0}), addMaterial(scene, "grey", diffuse(Vec3(0.5f))));
    scene.lights.push_back({});  // point light, intensity 1
    Light spot;
    spot.type = LightType::Spot;
    spot.intensity = 2.0f;
    spot.innerConeDegrees = 30.0f;
    spot.outerConeDegrees = 30.0f;
    scene.lights.push_back(spot);
    scene.environment.color = Vec3(0.5f);
    const CompiledScene compiled = compileRenderScene(scene);
    ASSERT_EQ(compiled.emitters.emitters.size(), 3u);
    EXPECT_EQ(compiled.stats.punctualLightCount, 2u);
    EXPECT_TRUE(compiled.stats.environmentSampled);
    EXPECT_NEAR(compiled.emitters.emitters[0].weight, 4.0f, 1e-5f);
    EXPECT_NEAR(compiled.emitters.emitters[1].weight, 2.0f * 2.0f * (1.0f - std::cos(kPi / 6)), 1e-5f);
    // Its flux share, 4 pi R^2 x 0.5 against the lights' 4.54, is 0.81: kept at 3/4.
    const float local = compiled.emitters.emitters[0].weight + compiled.emitters.emitters[1].weight;
    EXPECT_NEAR(compiled.emitters.emitters[2].weight, 3.0f * local, 1e-4f);
    EXPECT_EQ(compiled.environment.lightWeight, compiled.emitters.emitters[2].weight);
    EXPECT_NEAR(compiled.punctualLights[0].direction.z, -1.0f, 1e-6f);

    scene.lights.clear();
    const CompiledScene skyOnly = compileRenderScene(scene);
    ASSERT_EQ(skyOnly.emitters.emitters.size(), 1u);
    const float radius = std::sqrt(3.0f);  // the unit box's bounding sphere
    EXPECT_NEAR(skyOnly.emitters.emitters[0].weight, 4 * kPi * radius * radius * 0.5f, 1e-3f);
}

TEST(CompileScene, HiddenInstancesAndUnmappedSlotsAreHandled) {
    Scene scene = sceneWithGrid(2, 3);
    scene.instances[1].visible = false;
    scene.instances[2].materials.clear();  // falls back to the default material
    const CompiledScene compiled = compileRenderScene(scene);
    EXPECT_EQ(compiled.stats.instanceCount, 2u);
    EXPECT_EQ(compiled.instanceMaterials[compiled.instances[1].materialOffset],
              compiled.materials.size() - 1);
    EXPECT_EQ(compiled.sceneInstanceOf, (std::vector<uint32_t>{0u, 2u})) << "the hidden one has no entry";
    EXPECT_EQ(compiled.renderInstanceOf, (std::vector<uint32_t>{0u, kNotTraced, 1u}));
    EXPECT_EQ(sceneInstanceOfHit(compiled, 1), 2);
    EXPECT_EQ(sceneInstanceOfHit(compiled, 2), -1) << "past the traced instances";
}

// The light table skips meshes no instance shades with an emissive material (so a scene
// without emitters never walks its triangles), yet a mesh shared by an emissive and a plain
// instance, or emissive in one slot only, still gives exactly its emissive triangles.
TEST(CompileScene, LightTableHoldsEveryEmissiveTriangleAndNoOther) {
    Scene scene = sceneWithGrid(3, 3);  // 18 triangles a grid
    Material bright = diffuse({0, 0, 0});
    bright.emission = {1, 1, 1};
    const uint32_t light = addMaterial(scene, "light", bright);
    scene.meshes.push_back(gridMesh(2));  // 8 triangles, two slots: the first 3 in slot 1
    scene.meshes[1].slotCount = 2;
    scene.meshes[1].primitiveSlots = {1, 1, 1, 0, 0, 0, 0, 0};
    Instance twoSlots;
    twoSlots.mesh = 1;
    twoSlots.materials = {0, 0};
    scene.instances.push_back(twoSlots);
    CompiledScene plain = compileRenderScene(scene);
    EXPECT_EQ(plain.stats.emitterCount, 0u);
    EXPECT_EQ(plain.emitters.emitters.size(), 0u);

    scene.instances[1].materials = {light};  // the shared grid's second instance emits
    scene.instances[3].materials = {0, light};
    const CompiledScene compiled = compileRenderScene(scene);
    EXPECT_EQ(compiled.stats.emitterCount, 18u + 3u);
    for (const Emitter& e : compiled.emitters.emitters) {
        EXPECT_TRUE(e.instance == 1 || (e.instance == 3 && e.primitive < 3))
            << e.instance << " " << e.primitive;
    }
    // After an edit, the table is the one a fresh compile gives.
    compileInstances(scene, plain);
    compileLights(scene, plain, LightsUpdate::KeepEnvironment);
    ASSERT_EQ(plain.emitters.emitters.size(), compiled.emitters.emitters.size());
    for (size_t i = 0; i < plain.emitters.emitters.size(); ++i) {
        EXPECT_EQ(plain.emitters.emitters[i].instance, compiled.emitters.emitters[i].instance);
        EXPECT_EQ(plain.emitters.emitters[i].primitive, compiled.emitters.emitters[i].primitive);
        EXPECT_EQ(plain.emitters.emitters[i].weight, compiled.emitters.emitters[i].weight);
    }
}

TEST(CompileScene, ARefusedInstanceEditLeavesTheInstancesAsTheyWere) {
    Scene scene = sceneWithGrid(2, 3);
    CompiledScene compiled = compileRenderScene(scene);
    scene.instances[0].objectToWorld = translationTransform({5.0f, 0.0f, 0.0f});
    scene.instances[2].materials = {42};
    EXPECT_THROW(compileInstances(scene, compiled), std::invalid_argument);
    ASSERT_EQ(compiled.instances.size(), 3u);
    EXPECT_EQ(compiled.instances[0].objectToWorld.rows[0].w, 0.0f);
    EXPECT_EQ(compiled.instanceMaterials.size(), 3u);
}

}  // namespace
}  // namespace pt
