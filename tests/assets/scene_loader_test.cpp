// loadScene and the pieces scene JSON shares with model files: dispatch and errors,
// instancing (a file imported once, placed many times), relative paths, cameras.
#include "assets/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "assets/input_error.h"
#include "assets/scene_json/scene_json.h"
#include "scene_test_helpers.h"
#include "support/load_scene.h"

namespace pt {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::scenesEqual;
using test::testDataPath;
using test::testFolder;
using test::writeFile;

std::string normalized(const std::string& path) { return fs::path(path).lexically_normal().string(); }

void expectNear(Vec3 a, Vec3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SceneLoader, MissingFileIsNamed) {
    const std::string path = testFolder() + "/nothing.json";
    const LoadResult result = loadScene(path);
    EXPECT_FALSE(result.ok());
    EXPECT_EQ(result.error, path + ": no such file");
}

TEST(SceneLoader, UnknownExtensionIsRefused) {
    const std::string path = writeFile(testFolder(), "model.fbx", "binary");
    EXPECT_EQ(loadScene(path).error,
              path + ": unsupported file type \".fbx\" (expected .json, .gltf, .glb or .obj)");
}

TEST(SceneLoader, ModelFileBecomesOneObjectFramedByTheCamera) {
    const std::string path = testDataPath("json/models/panel.obj");
    const Scene scene = test::loadSceneOrFail(path);
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].kind, ObjectKind::File);
    EXPECT_EQ(scene.objects[0].path, normalized(path));
    EXPECT_EQ(scene.sourcePath, normalized(path));
    ASSERT_FALSE(scene.instances.empty());
    for (const Instance& instance : scene.instances) EXPECT_EQ(instance.object, 0);
    EXPECT_FALSE(scene.cameraFromFile);
    EXPECT_TRUE(test::bitsEqual(scene.camera.position, frameBounds(scene).position));
    EXPECT_EQ(scene.render.spp, RenderSettings{}.spp);
}

TEST(SceneLoader, UnlitModelFileGetsAWhiteEnvironmentAndSaysSo) {
    const Scene scene = test::loadSceneOrFail(testDataPath("json/models/panel.obj"));
    ASSERT_FALSE(sceneHasEmitters(scene));
    EXPECT_EQ(scene.environment.color, Vec3(1.0f));
    ASSERT_FALSE(scene.warnings.empty());
    EXPECT_NE(scene.warnings.back().find("panel.obj: no lights in the file"), std::string::npos);

    Scene lit = scene;  // a scene with its own light keeps its (black) environment
    lit.environment.color = Vec3(0.0f);
    lit.warnings.clear();
    lit.materials[lit.instances[0].materials[0]].params.emission = {1, 1, 1};
    lightUnlitModel(lit);
    EXPECT_EQ(lit.environment.color, Vec3(0.0f));
    EXPECT_TRUE(lit.warnings.empty());
}

TEST(SceneLoader, ModelFileCameraIsUsed) {
    const Scene scene = test::loadSceneOrFail(testDataPath("json/models/eye.gltf"));
    EXPECT_TRUE(scene.cameraFromFile);
    expectNear(scene.camera.position, {0.0f, 0.0f, 4.0f}, 1e-6f);
}

TEST(SceneLoader, SameFileThreeTimesIsImportedOnce) {
    const Scene single = test::loadSceneOrFail(testDataPath("json/models/panel.obj"));
    const std::string model = testDataPath("json/models/panel.obj");
    const Scene scene =
        test::loadSceneOrFail(writeFile(testFolder(), "three.json", R"({"version": 1, "objects": [
        {"file": ")" + model + R"("},
        {"file": ")" + model + R"(", "transform": {"translate": [3, 0, 0]}},
        {"file": ")" + model + R"(", "transform": {"rotate": [0, 90, 0], "scale": 2}}]})"));
    EXPECT_EQ(scene.meshes.size(), single.meshes.size()) << "one set of meshes, shared";
    EXPECT_EQ(scene.materials.size(), single.materials.size());
    ASSERT_EQ(scene.instances.size(), 3 * single.instances.size());
    const size_t perObject = single.instances.size();
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const Instance& original = single.instances[i % perObject];
        EXPECT_EQ(instance.object, int32_t(i / perObject));
        EXPECT_EQ(instance.mesh, original.mesh);
        EXPECT_EQ(instance.materials, original.materials);
        const Affine3 expected = scene.objects[i / perObject].transform.toAffine() * original.objectToWorld;
        EXPECT_TRUE(test::bitsEqual(instance.objectToWorld, expected)) << "instance " << i;
    }
}

TEST(SceneLoader, ShapesShareOneMeshPerKind) {
    const Scene scene =
        test::loadSceneOrFail(writeFile(testFolder(), "shapes.json", R"({"version": 1, "objects": [
        {"shape": "sphere"}, {"shape": "box"}, {"shape": "sphere", "transform": {"translate": [2, 0, 0]}},
        {"shape": "quad"}, {"shape": "box", "name": "crate"}, {"shape": "sphere"}]})"));
    EXPECT_EQ(scene.meshes.size(), 3u);
    ASSERT_EQ(scene.instances.size(), 6u);
    EXPECT_EQ(scene.instances[0].mesh, scene.instances[2].mesh);
    EXPECT_EQ(scene.instances[0].mesh, scene.instances[5].mesh);
    EXPECT_EQ(scene.instances[1].mesh, scene.instances[4].mesh);
    EXPECT_EQ(scene.instances[4].name, "crate");
    EXPECT_EQ(scene.instances[3].name, "quad");
    EXPECT_EQ(scene.materials.size(), 1u) << "one default material for all";
}

TEST(SceneLoader, CameraComesFromTheFirstFileThatHasOne) {
    const std::string folder = testFolder();
    const std::string objects = R"("objects": [{"file": ")" + testDataPath("json/models/panel.obj") +
                                R"("}, {"file": ")" + testDataPath("json/models/eye.gltf") +
                                R"(", "transform": {"translate": [10, 0, 0]}}])";
    const Scene fromFile =
        test::loadSceneOrFail(writeFile(folder, "a.json", R"({"version": 1, )" + objects + "}"));
    EXPECT_TRUE(fromFile.cameraFromFile);
    expectNear(fromFile.camera.position, {10.0f, 0.0f, 4.0f}, 1e-5f);
    const Scene fromJson = test::loadSceneOrFail(
        writeFile(folder, "b.json", R"({"version": 1, "camera": {"position": [0, 1, 9]}, )" + objects + "}"));
    EXPECT_EQ(fromJson.camera.position, Vec3(0.0f, 1.0f, 9.0f)) << "the JSON camera wins";
}

TEST(SceneLoader, FrameBoundsFitsTheBoundingSphere) {
    const std::string folder = testFolder();
    const std::string objects =
        R"("objects": [{"shape": "sphere", "transform": {"translate": [1, 2, 3], "scale": 2}}])";
    const Scene square =
        test::loadSceneOrFail(writeFile(folder, "square.json", R"({"version": 1, )" + objects + "}"));
    EXPECT_FALSE(square.cameraFromFile);
    const float radius = 2.0f * std::sqrt(3.0f);  // half the diagonal of the bounds
    const float halfFov = 22.5f * kPi / 180.0f;
    expectNear(square.camera.lookAt, {1.0f, 2.0f, 3.0f}, 1e-5f);
    expectNear(square.camera.position, {1.0f, 2.0f, 3.0f + radius / std::sin(halfFov)}, 1e-4f);
    EXPECT_EQ(square.camera.verticalFovDegrees, 45.0f);
    // A portrait image is narrower than it is tall: the horizontal field of view decides.
    const Scene portrait = test::loadSceneOrFail(writeFile(
        folder, "portrait.json", R"({"version": 1, "render": {"resolution": [200, 400]}, )" + objects + "}"));
    const float halfHorizontal = std::atan(std::tan(halfFov) * 0.5f);
    EXPECT_NEAR(portrait.camera.position.z, 3.0f + radius / std::sin(halfHorizontal), 1e-4f);
}

TEST(SceneLoader, InstantiateNamesInstancesAndAppliesOverrides) {
    Scene scene;
    scene.materials = {{"blue", Material{}, -1}, {"paint", Material{}, 0}, {"trim", Material{}, 0}};
    SceneObject object;
    object.name = "lamp";
    object.path = "/models/lamp.gltf";
    object.transform.translate = {0.0f, 5.0f, 0.0f};
    object.materialOverrides = {{"paint", "blue"}};
    scene.objects.push_back(object);
    ImportedFile file;
    file.placements.resize(2);
    file.placements[0].name = "shade";
    file.placements[0].materials = {1, 2};
    file.placements[1].fileToNode = translationTransform({1.0f, 0.0f, 0.0f});
    file.placements[1].materials = {1};
    instantiateImportedFile(file, 0, scene);
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[0].name, "shade");
    EXPECT_EQ(scene.instances[1].name, "lamp.1") << "unnamed placements are named after the object";
    EXPECT_EQ(scene.instances[0].materials, (std::vector<uint32_t>{0, 2}));
    EXPECT_EQ(scene.instances[1].materials, (std::vector<uint32_t>{0}));
    EXPECT_EQ(scene.instances[1].objectToWorld.translation(), Vec3(1.0f, 5.0f, 0.0f));

    scene.objects[0].materialOverrides = {{"glass", "blue"}};
    try {
        instantiateImportedFile(file, 0, scene);
        FAIL() << "accepted an override of a material the file does not have";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "objects[0].materialOverrides.glass: lamp.gltf has no material \"glass\"");
    }
}

TEST(SceneLoader, RelativePathsFollowTheSavedFile) {
    const Scene scene = test::loadSceneOrFail(testDataPath("json/scenes/relative.json"));
    const std::string model = normalized(testDataPath("json/models/panel.obj"));
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].path, model);
    EXPECT_NE(
        sceneToJson(scene, testDataPath("json/scenes/copy.json")).find(R"("file": "../models/panel.obj")"),
        std::string::npos);

    const std::string folder = testFolder() + "/deeper/still";
    fs::create_directories(folder);
    writeSceneJson(scene, folder + "/moved.json");
    const std::string relative = fs::path(model).lexically_relative(folder).generic_string();
    EXPECT_NE(readFile(folder + "/moved.json").find("\"file\": \"" + relative + "\""), std::string::npos)
        << readFile(folder + "/moved.json");
    EXPECT_TRUE(scenesEqual(scene, test::loadSceneOrFail(folder + "/moved.json")));
}

TEST(SceneLoader, ReportsLoadSceneProgress) {
    std::vector<double> fractions;
    (void)test::loadSceneOrFail(testDataPath("json/scenes/relative.json"),
                                [&](const std::string& stage, double fraction) {
                                    if (stage == "load scene") fractions.push_back(fraction);
                                });
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.back(), 1.0);
}

TEST(SceneLoader, FileCameraFollowsItsObject) {
    Camera camera;
    camera.position = {0.0f, 0.0f, 4.0f};
    camera.focusDistance = 3.0f;
    camera.apertureRadius = 0.1f;
    ObjectTransform transform;
    transform.translate = {10.0f, 0.0f, 0.0f};
    transform.scale = Vec3(2.0f);
    const Camera placed = cameraToWorld(camera, transform.toAffine());
    expectNear(placed.position, {10.0f, 0.0f, 8.0f}, 1e-6f);
    expectNear(placed.lookAt, {10.0f, 0.0f, 0.0f}, 1e-6f);
    expectNear(placed.up, {0.0f, 1.0f, 0.0f}, 1e-6f);
    EXPECT_FLOAT_EQ(placed.focusDistance, 6.0f);
    EXPECT_FLOAT_EQ(placed.apertureRadius, 0.2f);
}

}  // namespace
}  // namespace pt
