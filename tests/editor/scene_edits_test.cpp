// The value commands of editor/scene_edits.h: each changes what it names and nothing else,
// reports the SceneChanges the backend needs, and undo/redo give back the document bit for bit.
#include "editor/scene_edits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "assets/input_error.h"
#include "assets/scene_test_helpers.h"
#include "editor/command_stack.h"
#include "editor/scene_equality.h"
#include "render/scene/morph.h"
#include "support/load_scene.h"
#include "support/scene_builder.h"
#include "support/scene_delta_print.h"
#include "support/test_paths.h"

namespace pt::editor {
namespace {

using test::addLight;
using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::expectScenesEqual;
using test::trs;

void expectTogglesEqual(const IntegratorToggles& a, const IntegratorToggles& b) {
    EXPECT_EQ(a.nextEventEstimation, b.nextEventEstimation);
    EXPECT_EQ(a.multipleImportance, b.multipleImportance);
    EXPECT_EQ(a.russianRoulette, b.russianRoulette);
    EXPECT_EQ(a.bruteForce, b.bruteForce);
    EXPECT_EQ(a.clampRadiance, b.clampRadiance);
    EXPECT_EQ(a.pixelJitter, b.pixelJitter);
    EXPECT_EQ(a.megakernel, b.megakernel);
    EXPECT_EQ(a.pathRegeneration, b.pathRegeneration);
    EXPECT_EQ(a.streamCompaction, b.streamCompaction);
    EXPECT_EQ(a.materialSort, b.materialSort);
    EXPECT_EQ(a.firstHitCache, b.firstHitCache);
    EXPECT_EQ(a.rebuildSahRatio, b.rebuildSahRatio);
}

void expectViewersEqual(const ViewerSettings& a, const ViewerSettings& b) {
    EXPECT_EQ(a.display.exposureStops, b.display.exposureStops);
    EXPECT_EQ(a.display.toneMapper, b.display.toneMapper);
    EXPECT_EQ(a.display.whitePoint, b.display.whitePoint);
    EXPECT_EQ(a.display.dither, b.display.dither);
    EXPECT_EQ(a.builtinDisplay, b.builtinDisplay);
    EXPECT_EQ(a.aov, b.aov);
    EXPECT_EQ(a.exportAovs, b.exportAovs);
    EXPECT_EQ(a.exportHalf, b.exportHalf);
    EXPECT_EQ(a.samplesPerFrame, b.samplesPerFrame);
    EXPECT_EQ(a.targetSpp, b.targetSpp);
}

void expectDocumentsEqual(const Document& a, const Document& b) {
    expectScenesEqual(a.scene, b.scene);
    expectTogglesEqual(a.toggles, b.toggles);
    expectViewersEqual(a.viewer, b.viewer);
}

// Two shapes, two materials, a scene light: enough for every value command.
Document codeDocument() {
    Document doc;
    Scene& scene = doc.scene;
    scene.render = {16, 16, 3, 4, 0};
    const uint32_t red = addMaterial(scene, "red", diffuse({0.8f, 0.1f, 0.1f}));
    const uint32_t blue = addMaterial(scene, "blue", diffuse({0.1f, 0.1f, 0.8f}));
    addShape(scene, ObjectKind::Sphere, trs({-1.5f, 0, 0}), red, "ball");
    addShape(scene, ObjectKind::Box, trs({1.5f, 0, 0}, {0, 30, 0}, {0.5f, 0.5f, 0.5f}), blue, "crate");
    addLight(scene, LightType::Point, {1, 1, 1}, 10.0f, {0, 4, 0});
    scene.lights.back().name = "bulb";
    return doc;
}

// Applies `command` through a CommandStack, checks what it reports and that the document is
// `expected`, then that undo gives back the document as it was and redo the edited one, all
// bit for bit.
void checkEdit(Document& doc, std::unique_ptr<EditCommand> command, const SceneDelta& changes,
               const std::function<void(Document&)>& expectedEdit) {
    const Document before = doc;
    Document expected = doc;
    expectedEdit(expected);
    CommandStack stack;
    EXPECT_EQ(stack.execute(doc, std::move(command)), changes);
    {
        SCOPED_TRACE("after the edit");
        expectDocumentsEqual(expected, doc);
    }
    const Document after = doc;
    EXPECT_EQ(stack.undo(doc), changes);
    {
        SCOPED_TRACE("after undo");
        expectDocumentsEqual(before, doc);
    }
    EXPECT_EQ(stack.redo(doc), changes);
    {
        SCOPED_TRACE("after redo");
        expectDocumentsEqual(after, doc);
    }
}

TEST(SceneEdits, SetMaterialChangesOneMaterial) {
    Document doc = codeDocument();
    Material m = doc.scene.materials[1].params;
    m.baseColor = {0.2f, 0.9f, 0.3f};
    m.roughness = 0.125f;
    auto command = setMaterial(doc, 1, m);
    EXPECT_NE(command->label().find("blue"), std::string::npos) << command->label();
    checkEdit(doc, std::move(command), materialsEdited({1}),
              [&](Document& d) { d.scene.materials[1].params = m; });
}

TEST(SceneEdits, DragsOfOneMaterialFoldButNotOfTwo) {
    Document doc = codeDocument();
    const Document before = doc;
    CommandStack stack;
    for (float r : {0.1f, 0.2f, 0.3f}) {
        Material m = doc.scene.materials[0].params;
        m.roughness = r;
        stack.execute(doc, setMaterial(doc, 0, m));
    }
    Material other = doc.scene.materials[1].params;
    other.metallic = 1.0f;
    stack.execute(doc, setMaterial(doc, 1, other));
    EXPECT_EQ(stack.undoDepth(), 2u);
    stack.undo(doc);
    stack.undo(doc);
    expectDocumentsEqual(before, doc);
}

TEST(SceneEdits, SetInstanceTransformMovesOneInstance) {
    Document doc = codeDocument();
    const Affine3 moved = trs({0.25f, 1, -2}, {10, 20, 30}, {1, 2, 3}).toAffine();
    checkEdit(doc, setInstanceTransform(doc, 1, moved), instancesMoved({1}),
              [&](Document& d) { d.scene.instances[1].objectToWorld = moved; });
}

TEST(SceneEdits, SetLightChangesOneLight) {
    Document doc = codeDocument();
    Light light = doc.scene.lights[0];
    light.type = LightType::Spot;
    light.intensity = 3.5f;
    light.position = {1, 2, 3};
    light.direction = {0, -1, 0};
    light.outerConeDegrees = 20.0f;
    checkEdit(doc, setLight(doc, 0, light), SceneChanges::Lights,
              [&](Document& d) { d.scene.lights[0] = light; });
}

TEST(SceneEdits, SetCamera) {
    Document doc = codeDocument();
    Camera camera = doc.scene.camera;
    camera.position = {3, 2, 1};
    camera.verticalFovDegrees = 30.0f;
    camera.apertureRadius = 0.05f;
    camera.focusDistance = 4.0f;
    checkEdit(doc, setCamera(doc, camera), SceneChanges::Camera,
              [&](Document& d) { d.scene.camera = camera; });
}

TEST(SceneEdits, SetRenderSettings) {
    Document doc = codeDocument();
    RenderSettings settings = doc.scene.render;
    settings.maxDepth = 7;
    settings.width = 24;
    settings.seed = 9;
    checkEdit(doc, setRenderSettings(doc, settings), SceneChanges::Settings,
              [&](Document& d) { d.scene.render = settings; });
}

TEST(SceneEdits, SetEnvironment) {
    Document doc = codeDocument();
    Environment environment = doc.scene.environment;
    environment.color = {0.1f, 0.2f, 0.3f};
    environment.intensity = 2.0f;
    environment.rotationDegrees = 45.0f;
    checkEdit(doc, setEnvironment(doc, environment), SceneChanges::Environment,
              [&](Document& d) { d.scene.environment = environment; });
}

// A 4x2 Radiance .hdr of (1, 0.5, 0.25) (flat RGBE scanlines: narrower than 8, so not RLE).
std::string writeTinyHdr(const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n";
    for (int i = 0; i < 8; ++i) out << char(128) << char(64) << char(32) << char(129);
    return path;
}

// An environment image chosen in the Environment panel: decoded when the command is made, put
// into Scene::textures once (undo keeps it, redo finds it again), strength and rotation kept.
TEST(SceneEdits, SetEnvironmentImage) {
    Document doc = codeDocument();
    doc.scene.environment.intensity = 3.0f;
    doc.scene.environment.rotationDegrees = 30.0f;
    const size_t textures = doc.scene.textures.size();
    const std::string path = writeTinyHdr(test::testFolder() + "/sky.hdr");
    CommandStack stack;
    EXPECT_EQ(stack.execute(doc, setEnvironmentImage(doc, path)),
              SceneChanges::Environment | SceneChanges::Textures);
    ASSERT_EQ(doc.scene.textures.size(), textures + 1);
    const Environment& e = doc.scene.environment;
    EXPECT_EQ(e.texture, int32_t(textures));
    EXPECT_EQ(e.imagePath, std::filesystem::absolute(path).lexically_normal().string());
    EXPECT_EQ(e.intensity, 3.0f);
    EXPECT_EQ(e.rotationDegrees, 30.0f);
    const Texture& image = doc.scene.textures.back();
    ASSERT_EQ(image.width, 4u);
    ASSERT_EQ(image.format, TexelFormat::RGBA32F);
    EXPECT_EQ(image.texelsF[1], 0.5f);
    EXPECT_EQ(stack.undoLabel(), "Environment: image sky.hdr");

    EXPECT_EQ(stack.undo(doc), SceneChanges::Environment);
    EXPECT_EQ(doc.scene.environment.texture, -1);
    EXPECT_EQ(stack.redo(doc), SceneChanges::Environment) << "the image is there already";
    EXPECT_EQ(doc.scene.textures.size(), textures + 1);
    EXPECT_EQ(doc.scene.environment.texture, int32_t(textures));

    EXPECT_THROW(setEnvironmentImage(doc, test::testFolder() + "/missing.hdr"), InputError);
}

TEST(SceneEdits, SetTogglesChangesNoScene) {
    Document doc = codeDocument();
    IntegratorToggles toggles = doc.toggles;
    toggles.nextEventEstimation = false;
    toggles.clampRadiance = 10.0f;
    checkEdit(doc, setToggles(doc, toggles), SceneChanges::Settings,
              [&](Document& d) { d.toggles = toggles; });
}

TEST(SceneEdits, SetViewerIsDisplayOnly) {
    Document doc = codeDocument();
    ViewerSettings viewer = doc.viewer;
    viewer.display.exposureStops = 1.5f;
    viewer.display.toneMapper = ToneMapper::AcesFitted;
    viewer.targetSpp = 16;
    checkEdit(doc, setViewer(doc, viewer), SceneChanges::Display, [&](Document& d) { d.viewer = viewer; });
}

TEST(SceneEdits, SetColorSettingsIsDisplayOnlyAndSaved) {
    Document doc = codeDocument();
    ColorSettings color;
    color.display = "Rec.1886";
    color.view = "ACES 1.0 SDR";
    color.look = "Exposure -1";
    checkEdit(doc, setColorSettings(doc, color), SceneChanges::Display,
              [&](Document& d) { d.scene.color = color; });
}

void expectNear(const Affine3& expected, const Affine3& actual, const std::string& where) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            const float e = expected.at(r, c), a = actual.at(r, c);
            EXPECT_NEAR(a, e, 1e-5f * (1.0f + std::fabs(e))) << where << " row " << r << " column " << c;
        }
    }
}

void expectNear(Vec3 expected, Vec3 actual, const std::string& where) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(actual[i], expected[i], 1e-5f * (1.0f + std::fabs(expected[i]))) << where;
}

// The instances object `object` places, in scene order.
std::vector<uint32_t> instancesOf(const Scene& scene, int32_t object) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        if (scene.instances[i].object == object) out.push_back(i);
    }
    return out;
}

TEST(SceneEdits, SetObjectTransformOfAShapeMovesItsInstance) {
    Document doc = codeDocument();
    const ObjectTransform after = trs({0, 1, 2}, {0, 90, 0}, {2, 2, 2});
    const Document before = doc;
    CommandStack stack;
    EXPECT_EQ(stack.execute(doc, setObjectTransform(doc, 1, after)),
              instancesMoved(instancesOf(doc.scene, 1)));
    expectNear(after.toAffine(), doc.scene.instances[1].objectToWorld, "crate");
    Document expected = before;
    expected.scene.objects[1].transform = after;
    expected.scene.instances[1].objectToWorld = doc.scene.instances[1].objectToWorld;  // checked above
    expectDocumentsEqual(expected, doc);
    stack.undo(doc);
    expectDocumentsEqual(before, doc);
}

// A scene JSON with two model files (one with a node hierarchy, one with lights), a shape and
// a scene light, written into the test's folder with absolute paths to the test data.
Scene fileScene() {
    const std::string folder = test::testFolder();
    const std::string json = R"({
  "version": 1,
  "render": {"resolution": [16, 16], "spp": 1, "maxDepth": 2},
  "materials": [{"name": "white", "type": "diffuse", "baseColor": [0.7, 0.7, 0.7]}],
  "lights": [{"name": "key", "type": "point", "intensity": 5, "position": [0, 3, 0]}],
  "objects": [
    {"name": "nodes", "file": ")" +
                             test::testDataPath("gltf/transforms.gltf") + R"(",
     "transform": {"translate": [1, 2, 3], "rotate": [10, 20, 30], "scale": [1, 2, 1]}},
    {"name": "lamps", "file": ")" +
                             test::testDataPath("gltf/lights.gltf") + R"(",
     "transform": {"translate": [0, 1, 0], "rotate": [0, 45, 0]}},
    {"name": "ball", "shape": "sphere", "material": "white"}
  ]
})";
    return test::loadSceneOrFail(test::writeFile(folder, "scene.json", json));
}

TEST(SceneEdits, SetObjectTransformKeepsInstancesRelativeToTheObject) {
    Document doc;
    doc.scene = fileScene();
    ASSERT_EQ(doc.scene.objects.size(), 3u);
    const std::vector<uint32_t> placed = instancesOf(doc.scene, 0);
    ASSERT_GE(placed.size(), 3u) << "transforms.gltf places its mesh three times";
    const Document before = doc;
    const Affine3 objectBefore = doc.scene.objects[0].transform.toAffine();
    const ObjectTransform after = trs({-2, 0.5f, 4}, {0, -60, 15}, {0.5f, 0.5f, 1.5f});

    CommandStack stack;
    EXPECT_EQ(stack.execute(doc, setObjectTransform(doc, 0, after)),
              instancesMoved(instancesOf(doc.scene, 0)))
        << "the object places no lights";
    Document expected = before;
    expected.scene.objects[0].transform = after;
    for (size_t i : placed) {
        const Affine3 relative = inverse(objectBefore) * before.scene.instances[i].objectToWorld;
        expectNear(after.toAffine() * relative, doc.scene.instances[i].objectToWorld,
                   "instance " + doc.scene.instances[i].name);
        expected.scene.instances[i].objectToWorld = doc.scene.instances[i].objectToWorld;
    }
    {
        SCOPED_TRACE("nothing but the object and its instances moved");
        expectDocumentsEqual(expected, doc);
    }
    const Document moved = doc;
    EXPECT_EQ(stack.undo(doc), instancesMoved(placed)) << "an undo names the same instances";
    {
        SCOPED_TRACE("undo");
        expectDocumentsEqual(before, doc);
    }
    stack.redo(doc);
    {
        SCOPED_TRACE("redo");
        expectDocumentsEqual(moved, doc);
    }
}

TEST(SceneEdits, SetObjectTransformMovesTheFilesLights) {
    Document doc;
    doc.scene = fileScene();
    const int32_t lamps = 1;
    size_t fileLights = 0;
    for (const Light& light : doc.scene.lights) fileLights += light.object == lamps ? 1 : 0;
    ASSERT_EQ(fileLights, 3u) << "lights.gltf has three lights";
    const Document before = doc;
    const Affine3 objectBefore = doc.scene.objects[lamps].transform.toAffine();
    const ObjectTransform after = trs({5, 0, -1}, {90, 0, 0}, {2, 2, 2});

    CommandStack stack;
    SceneDelta lampsMoved = instancesMoved(instancesOf(doc.scene, lamps));
    lampsMoved |= SceneChanges::Lights;
    EXPECT_EQ(stack.execute(doc, setObjectTransform(doc, lamps, after)), lampsMoved);
    const Affine3 delta = after.toAffine() * inverse(objectBefore);
    for (size_t i = 0; i < doc.scene.lights.size(); ++i) {
        const Light& was = before.scene.lights[i];
        const Light& now = doc.scene.lights[i];
        if (was.object != lamps) {
            test::expectLightsEqual(was, now, "scene light " + was.name);
            continue;
        }
        expectNear(delta.transformPoint(was.position), now.position, "light " + was.name + " position");
        expectNear(delta.transformVector(was.direction), now.direction, "light " + was.name + " direction");
        EXPECT_EQ(now.intensity, was.intensity);
    }
    for (size_t i : instancesOf(doc.scene, lamps)) {
        const Affine3 relative = inverse(objectBefore) * before.scene.instances[i].objectToWorld;
        expectNear(after.toAffine() * relative, doc.scene.instances[i].objectToWorld, "lamps instance");
    }
    for (size_t i : instancesOf(doc.scene, 0)) {
        test::expectSameBits(before.scene.instances[i].objectToWorld, doc.scene.instances[i].objectToWorld,
                             "another object's instance");
    }
    EXPECT_EQ(stack.undo(doc), lampsMoved);
    expectDocumentsEqual(before, doc);
}

TEST(SceneEdits, AnObjectDragIsOneUndoStepBackToTheStart) {
    Document doc;
    doc.scene = fileScene();
    const Document before = doc;
    CommandStack stack;
    for (float x : {0.5f, 1.0f, 1.5f, 2.0f}) {
        ObjectTransform t = doc.scene.objects[0].transform;
        t.translate.x = x;
        stack.execute(doc, setObjectTransform(doc, 0, t));
    }
    EXPECT_EQ(stack.undoDepth(), 1u);
    EXPECT_EQ(doc.scene.objects[0].transform.translate.x, 2.0f);
    stack.undo(doc);
    expectDocumentsEqual(before, doc);
}

// A triangle with two morph targets, placed by two objects; a third object (a sphere) does not
// use it.
Document morphDocument() {
    Document doc;
    Scene& scene = doc.scene;
    const uint32_t white = addMaterial(scene, "white", diffuse({0.5f, 0.5f, 0.5f}));
    Mesh mesh;
    mesh.name = "blob";
    mesh.basePositions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.baseNormals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.indices = {0, 1, 2};
    mesh.morphTargets = {
        {"up", {{0, 0.5f, 0}, {0, 0.25f, 0}, {0, 1, 0}}, {}},
        {"side", {{1, 0, 0}, {0.5f, 0, 0.5f}, {0, 0, 0}}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 0}}}};
    mesh.morphWeights = {0.25f, 0.0f};
    mesh.defaultMorphWeights = {0.0f, 0.0f};
    applyMorphWeights(mesh);
    scene.meshes.push_back(mesh);
    for (const char* name : {"first", "second"}) {
        SceneObject object;
        object.name = name;
        object.kind = ObjectKind::File;
        object.path = "/nowhere/blob.gltf";
        object.morphWeights["other mesh"] = {1.0f};  // recorded for another mesh: kept
        scene.objects.push_back(object);
        Instance instance;
        instance.name = name;
        instance.mesh = 0;
        instance.materials = {white};
        instance.object = int32_t(scene.objects.size() - 1);
        scene.instances.push_back(instance);
    }
    addShape(scene, ObjectKind::Sphere, trs({3, 0, 0}), white, "ball");
    return doc;
}

TEST(SceneEdits, SetMorphWeightsDeformsAndRecordsTheWeights) {
    Document doc = morphDocument();
    const Document before = doc;
    const std::vector<float> weights = {0.5f, -1.0f};
    CommandStack stack;
    EXPECT_EQ(stack.execute(doc, setMorphWeights(doc, 0, weights)), meshesMoved({0}));

    const Mesh& base = before.scene.meshes[0];
    const Mesh& mesh = doc.scene.meshes[0];
    EXPECT_EQ(mesh.morphWeights, weights);
    ASSERT_EQ(mesh.positions.size(), 3u);
    for (size_t v = 0; v < 3; ++v) {
        const Vec3 expected = base.basePositions[v] + 0.5f * base.morphTargets[0].positionDeltas[v] -
                              base.morphTargets[1].positionDeltas[v];
        expectNear(expected, mesh.positions[v], "vertex " + std::to_string(v));
    }
    // The "side" target moves normals of vertices 0 and 1: (0,0,1) - (1,0,0) normalised.
    expectNear(normalize(Vec3(-1, 0, 1)), mesh.normals[0], "normal 0");
    for (size_t o = 0; o < 2; ++o) {
        const auto& recorded = doc.scene.objects[o].morphWeights;
        ASSERT_EQ(recorded.count("blob"), 1u) << doc.scene.objects[o].name;
        EXPECT_EQ(recorded.at("blob"), weights);
        EXPECT_EQ(recorded.at("other mesh"), std::vector<float>{1.0f});
    }
    EXPECT_TRUE(doc.scene.objects[2].morphWeights.empty()) << "the sphere does not place the mesh";

    Document expected = before;
    for (size_t o = 0; o < 2; ++o) expected.scene.objects[o].morphWeights["blob"] = weights;
    expected.scene.meshes[0].positions = mesh.positions;
    expected.scene.meshes[0].normals = mesh.normals;
    expectDocumentsEqual(expected, doc);

    const Document after = doc;
    EXPECT_EQ(stack.undo(doc), meshesMoved({0})) << "an undo names the same mesh";
    expectDocumentsEqual(before, doc);
    EXPECT_EQ(doc.scene.meshes[0].morphWeights, before.scene.meshes[0].morphWeights);
    stack.redo(doc);
    expectDocumentsEqual(after, doc);
}

}  // namespace
}  // namespace pt::editor
