// Saving an edited scene: a loaded scene saves and loads back equal; an edit to a material
// imported from a model file is saved as a scene material plus a materialOverride, so it
// survives loading; the scene in memory is never changed by saving, and a failed save throws
// InputError and leaves the previous file alone.
#include "editor/scene_saving.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "assets/input_error.h"
#include "assets/scene_test_helpers.h"
#include "editor/scene_equality.h"
#include "support/load_scene.h"
#include "support/test_paths.h"

namespace pt::editor {
namespace {

using test::expectScenesEqual;

TEST(SceneSaving, CornellSavesAndLoadsBackEqual) {
    Scene scene = test::loadSceneOrFail(test::projectPath("scenes/cornell.json"));
    ASSERT_FALSE(scene.objects.empty());
    const Scene before = scene;
    const std::string path = test::testFolder() + "/cornell.json";
    saveSceneJson(scene, materialParams(scene), path);
    {
        SCOPED_TRACE("the scene in memory");
        expectScenesEqual(before, scene);
    }
    const Scene loaded = test::loadSceneOrFail(path);
    SCOPED_TRACE("the scene loaded from " + path);
    expectScenesEqual(before, loaded);
}

// A model file with two named materials ("Everything", with an image embedded in the file,
// and "Defaults") and a shape.
Scene modelScene(const std::string& folder) {
    const std::string json = R"({
  "version": 1,
  "render": {"resolution": [16, 16], "spp": 1},
  "materials": [{"name": "white", "type": "diffuse", "baseColor": [0.7, 0.7, 0.7]}],
  "objects": [
    {"name": "mats", "file": ")" +
                             test::testDataPath("gltf/materials.gltf") + R"("},
    {"name": "ball", "shape": "sphere", "material": "white"}
  ]
})";
    return test::loadSceneOrFail(test::writeFile(folder, "scene.json", json));
}

int32_t importedMaterial(const Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].name == name && scene.materials[i].object >= 0) return int32_t(i);
    }
    return -1;
}

TEST(SceneSaving, AnEditedImportedMaterialIsSavedAsAnOverride) {
    const std::string folder = test::testFolder();
    Scene scene = modelScene(folder);
    const std::vector<Material> atLoad = materialParams(scene);
    const int32_t defaults = importedMaterial(scene, "Defaults");
    ASSERT_GE(defaults, 0);
    Material edited = scene.materials[size_t(defaults)].params;
    edited.baseColor = {0.25f, 0.5f, 0.75f};
    edited.roughness = 0.125f;
    edited.metallic = 0.5f;
    scene.materials[size_t(defaults)].params = edited;
    const Scene before = scene;

    const std::string path = folder + "/saved.json";
    saveSceneJson(scene, atLoad, path);
    {
        SCOPED_TRACE("saving leaves the scene as it was (names, owners, overrides)");
        expectScenesEqual(before, scene);
    }

    const Scene loaded = test::loadSceneOrFail(path);
    ASSERT_EQ(loaded.objects.size(), 2u);
    const SceneObject& mats = loaded.objects[0];
    ASSERT_EQ(mats.materialOverrides.count("Defaults"), 1u) << test::readFile(path);
    EXPECT_EQ(mats.materialOverrides.count("Everything"), 0u) << "an unedited material needs no override";
    const int32_t saved = loaded.findMaterial(mats.materialOverrides.at("Defaults"));
    ASSERT_GE(saved, 0);
    EXPECT_EQ(loaded.materials[size_t(saved)].object, -1) << "a scene material";
    EXPECT_EQ(std::memcmp(&loaded.materials[size_t(saved)].params, &edited, sizeof(Material)), 0)
        << "the loaded scene has the edited parameters";
    // The file's instance now uses it for the slot that had "Defaults".
    bool used = false;
    for (const Instance& instance : loaded.instances) {
        if (instance.object != 0) continue;
        for (size_t slot = 0; slot < instance.materials.size(); ++slot) {
            const uint32_t was = before.instances[0].materials.at(slot);
            if (was == uint32_t(defaults)) {
                EXPECT_EQ(instance.materials[slot], uint32_t(saved));
                used = true;
            }
        }
    }
    EXPECT_TRUE(used);
    // Saving the loaded scene again writes the same file: nothing is adopted twice.
    Scene again = loaded;
    const std::string second = folder + "/saved again.json";
    saveSceneJson(again, materialParams(again), second);
    EXPECT_EQ(test::readFile(second), test::readFile(path));
}

TEST(SceneSaving, AFailedSaveKeepsTheSceneAndThePreviousFile) {
    const std::string folder = test::testFolder();
    Scene scene = modelScene(folder);
    const std::vector<Material> atLoad = materialParams(scene);
    // "Everything" samples an image embedded in the model file, which scene JSON cannot name:
    // saving the edited material must fail.
    const int32_t everything = importedMaterial(scene, "Everything");
    ASSERT_GE(everything, 0);
    scene.materials[size_t(everything)].params.roughness = 0.9f;
    const Scene before = scene;
    const std::string path = test::writeFile(folder, "existing.json", "previous contents");
    EXPECT_THROW(saveSceneJson(scene, atLoad, path), InputError);
    expectScenesEqual(before, scene);
    EXPECT_EQ(test::readFile(path), "previous contents");
}

TEST(SceneSaving, SavingIntoAMissingFolderThrowsNamingTheFile) {
    const std::string folder = test::testFolder();
    Scene scene = modelScene(folder);
    const Scene before = scene;
    const std::string path = folder + "/no such folder/scene.json";
    try {
        saveSceneJson(scene, materialParams(scene), path);
        ADD_FAILURE() << "saving into a missing folder succeeded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("scene.json"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    expectScenesEqual(before, scene);
}

}  // namespace
}  // namespace pt::editor
