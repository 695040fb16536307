// The outliner commands of editor/object_edits.h on a loaded scene with model files: each
// rearranges exactly what it should (renumbering owners after a delete), reports the
// SceneChanges the backend needs, and undo/redo give back the scene bit for bit.
#include "editor/object_edits.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "assets/scene_loader.h"
#include "assets/scene_test_helpers.h"
#include "editor/command_stack.h"
#include "editor/scene_equality.h"
#include "editor/selection_box.h"
#include "support/load_scene.h"
#include "support/scene_delta_print.h"
#include "support/test_paths.h"

namespace pt::editor {
namespace {

using test::expectScenesEqual;

constexpr int32_t kNodes = 0, kMats = 1, kLamps = 2, kBall = 3;

// Objects: a node hierarchy (no materials, no lights), a file with named materials and
// textures, a file with three lights, a sphere; and one light of the scene's own.
Document fileDocument() {
    const std::string folder = test::testFolder();
    const std::string json = R"({
  "version": 1,
  "render": {"resolution": [16, 16], "spp": 1, "maxDepth": 2},
  "materials": [{"name": "white", "type": "diffuse", "baseColor": [0.7, 0.7, 0.7]}],
  "lights": [{"name": "key", "type": "point", "intensity": 5, "position": [0, 3, 0]}],
  "objects": [
    {"name": "nodes", "file": ")" +
                             test::testDataPath("gltf/transforms.gltf") + R"(",
     "transform": {"translate": [1, 2, 3]}},
    {"name": "mats", "file": ")" +
                             test::testDataPath("gltf/materials.gltf") + R"(",
     "transform": {"translate": [0, 0, -2]}},
    {"name": "lamps", "file": ")" +
                             test::testDataPath("gltf/lights.gltf") + R"(",
     "transform": {"translate": [0, 1, 0], "rotate": [0, 45, 0]}},
    {"name": "ball", "shape": "sphere", "material": "white", "transform": {"translate": [2, 0, 0]}}
  ]
})";
    Document doc;
    doc.scene = test::loadSceneOrFail(test::writeFile(folder, "scene.json", json));
    return doc;
}

// Executes `command`, checks its report and that the scene is `expected` (built from the scene
// before by `expectedEdit`), then undo and redo, bit for bit.
void checkEdit(Document& doc, std::unique_ptr<EditCommand> command, const SceneDelta& changes,
               const std::function<void(Scene&)>& expectedEdit) {
    const Scene before = doc.scene;
    Scene expected = doc.scene;
    expectedEdit(expected);
    CommandStack stack;
    EXPECT_EQ(stack.execute(doc, std::move(command)), changes);
    {
        SCOPED_TRACE("after the edit");
        expectScenesEqual(expected, doc.scene);
    }
    const Scene after = doc.scene;
    EXPECT_EQ(stack.undo(doc), changes);
    {
        SCOPED_TRACE("after undo");
        expectScenesEqual(before, doc.scene);
    }
    EXPECT_EQ(stack.redo(doc), changes);
    {
        SCOPED_TRACE("after redo");
        expectScenesEqual(after, doc.scene);
    }
}

size_t countInstances(const Scene& scene, int32_t object) {
    size_t n = 0;
    for (const Instance& instance : scene.instances) n += instance.object == object ? 1 : 0;
    return n;
}

size_t countLights(const Scene& scene, int32_t object) {
    size_t n = 0;
    for (const Light& light : scene.lights) n += light.object == object ? 1 : 0;
    return n;
}

TEST(ObjectEdits, TheTestSceneHasWhatTheTestsNeed) {
    const Document doc = fileDocument();
    ASSERT_EQ(doc.scene.objects.size(), 4u);
    EXPECT_GE(countInstances(doc.scene, kNodes), 3u);
    EXPECT_GE(countInstances(doc.scene, kMats), 1u);
    EXPECT_EQ(countLights(doc.scene, kLamps), 3u);
    EXPECT_EQ(countLights(doc.scene, -1), 1u);
    size_t namedMaterials = 0, matsTextures = 0;
    for (const NamedMaterial& m : doc.scene.materials) {
        namedMaterials += m.object == kMats && (m.name == "Everything" || m.name == "Defaults") ? 1 : 0;
    }
    for (const Texture& t : doc.scene.textures) matsTextures += t.object == kMats ? 1 : 0;
    EXPECT_EQ(namedMaterials, 2u) << "materials.gltf: Everything and Defaults";
    EXPECT_GE(matsTextures, 1u);
}

TEST(ObjectEdits, RenameAShapeRenamesItsInstance) {
    Document doc = fileDocument();
    ASSERT_EQ(doc.scene.instances.back().name, "ball");
    checkEdit(doc, renameObject(doc, kBall, "orb"), SceneChanges::None, [](Scene& s) {
        s.objects[kBall].name = "orb";
        s.instances.back().name = "orb";
    });
}

TEST(ObjectEdits, RenameAFileObjectKeepsTheFilesNodeNames) {
    Document doc = fileDocument();
    checkEdit(doc, renameObject(doc, kNodes, "hierarchy"), SceneChanges::None, [](Scene& s) {
        s.objects[kNodes].name = "hierarchy";
        for (Instance& instance : s.instances) {
            if (instance.object != kNodes) continue;
            // Names from the file stay; names made from the object's follow it.
            if (instance.name.rfind("nodes.", 0) == 0) instance.name = "hierarchy" + instance.name.substr(5);
        }
    });
}

TEST(ObjectEdits, HideAndShowAnObject) {
    Document doc = fileDocument();
    EXPECT_FALSE(objectHidden(doc.scene, kNodes));
    EXPECT_EQ(setObjectHidden(doc, kNodes, true)->label(), "Hide nodes");
    EXPECT_EQ(setObjectHidden(doc, kNodes, false)->label(), "Show nodes");
    checkEdit(doc, setObjectHidden(doc, kNodes, true), SceneChanges::Transforms, [](Scene& s) {
        for (Instance& instance : s.instances) {
            if (instance.object == kNodes) instance.visible = false;
        }
    });
    EXPECT_TRUE(objectHidden(doc.scene, kNodes));
    EXPECT_FALSE(objectHidden(doc.scene, kMats));
    checkEdit(doc, setObjectHidden(doc, kNodes, false), SceneChanges::Transforms, [](Scene& s) {
        for (Instance& instance : s.instances) instance.visible = true;
    });
    EXPECT_FALSE(objectHidden(doc.scene, kNodes));
}

TEST(ObjectEdits, AnObjectWithoutInstancesIsNotHidden) {
    Document doc = fileDocument();
    doc.scene.objects.push_back(SceneObject{});
    EXPECT_FALSE(objectHidden(doc.scene, uint32_t(doc.scene.objects.size() - 1)));
}

// What deleting object `removed` must give: its instances and lights gone, later objects'
// indices moved down by one, and its imported materials and textures orphaned (-2).
void expectedDelete(Scene& s, int32_t removed) {
    auto renumber = [removed](int32_t owner) {
        return owner == removed ? -2 : owner > removed ? owner - 1 : owner;
    };
    s.objects.erase(s.objects.begin() + removed);
    std::vector<Instance> instances;
    for (Instance instance : s.instances) {
        if (instance.object == removed) continue;
        instance.object = renumber(instance.object);
        instances.push_back(instance);
    }
    s.instances = instances;
    std::vector<Light> lights;
    for (Light light : s.lights) {
        if (light.object == removed) continue;
        light.object = renumber(light.object);
        lights.push_back(light);
    }
    s.lights = lights;
    for (NamedMaterial& m : s.materials) m.object = renumber(m.object);
    for (Texture& t : s.textures) t.object = renumber(t.object);
}

TEST(ObjectEdits, DeleteRenumbersLaterObjectsAndOrphansImportedMaterials) {
    Document doc = fileDocument();
    const size_t instanceCount = doc.scene.instances.size();
    const size_t matsInstances = countInstances(doc.scene, kMats);
    EXPECT_EQ(deleteObject(doc, kMats)->label(), "Delete mats");
    checkEdit(doc, deleteObject(doc, kMats), SceneChanges::Transforms,
              [](Scene& s) { expectedDelete(s, kMats); });
    // Spelled out for the redone state:
    EXPECT_EQ(doc.scene.objects.size(), 3u);
    EXPECT_EQ(doc.scene.objects[1].name, "lamps");
    EXPECT_EQ(doc.scene.instances.size(), instanceCount - matsInstances);
    EXPECT_EQ(doc.scene.instances.back().object, 2) << "the ball was object 3";
    EXPECT_EQ(countLights(doc.scene, 1), 3u) << "the lamps' lights follow their object to index 1";
    EXPECT_EQ(countLights(doc.scene, -1), 1u);
    for (const NamedMaterial& m : doc.scene.materials) {
        if (m.name == "Everything" || m.name == "Defaults") {
            EXPECT_EQ(m.object, -2) << m.name;
        }
    }
}

TEST(ObjectEdits, DeleteAnObjectWithLights) {
    Document doc = fileDocument();
    checkEdit(doc, deleteObject(doc, kLamps), SceneChanges::Transforms | SceneChanges::Lights,
              [](Scene& s) { expectedDelete(s, kLamps); });
    ASSERT_EQ(doc.scene.lights.size(), 1u);
    EXPECT_EQ(doc.scene.lights[0].name, "key");
}

TEST(ObjectEdits, DeleteTheFirstObject) {
    Document doc = fileDocument();
    checkEdit(doc, deleteObject(doc, kNodes), SceneChanges::Transforms,
              [](Scene& s) { expectedDelete(s, kNodes); });
}

TEST(ObjectEdits, DuplicateAFileObjectWithLights) {
    Document doc = fileDocument();
    EXPECT_EQ(duplicateObject(doc, kLamps)->label(), "Duplicate lamps");
    checkEdit(doc, duplicateObject(doc, kLamps), SceneChanges::Transforms | SceneChanges::Lights,
              [](Scene& s) {
                  const int32_t copy = int32_t(s.objects.size());
                  SceneObject object = s.objects[kLamps];
                  object.name = "lamps copy";
                  s.objects.push_back(object);
                  const size_t instanceCount = s.instances.size(), lightCount = s.lights.size();
                  for (size_t i = 0; i < instanceCount; ++i) {
                      if (s.instances[i].object != kLamps) continue;
                      Instance instance = s.instances[i];
                      instance.name += " copy";
                      instance.object = copy;
                      s.instances.push_back(instance);
                  }
                  for (size_t i = 0; i < lightCount; ++i) {
                      if (s.lights[i].object != kLamps) continue;
                      Light light = s.lights[i];
                      light.object = copy;
                      s.lights.push_back(light);
                  }
              });
    EXPECT_EQ(doc.scene.objects.back().name, "lamps copy");
    EXPECT_EQ(countInstances(doc.scene, 4), countInstances(doc.scene, kLamps));
    EXPECT_EQ(countLights(doc.scene, 4), 3u);
}

TEST(ObjectEdits, DuplicateAShape) {
    Document doc = fileDocument();
    checkEdit(doc, duplicateObject(doc, kBall), SceneChanges::Transforms, [](Scene& s) {
        SceneObject object = s.objects[kBall];
        object.name = "ball copy";
        s.objects.push_back(object);
        Instance instance = s.instances.back();
        instance.name = "ball copy";
        instance.object = 4;
        s.instances.push_back(instance);
    });
}

TEST(ObjectEdits, ADuplicateStandsBesideTheOriginal) {
    Document doc = fileDocument();
    doc.scene.camera.position = {0, 0, 10};
    doc.scene.camera.lookAt = {0, 0, 0};  // the camera's right is +X
    const Vec3 offset = duplicateOffset(doc.scene, kBall);
    const std::optional<WorldBox> box = selectionBounds(doc.scene, kBall, -1);
    ASSERT_TRUE(box.has_value());
    EXPECT_NEAR(offset.x, -1.1f * (box->hi.x - box->lo.x), 1e-5f)
        << "its width and a tenth, to the left: it stands right of the middle";
    EXPECT_EQ(offset.y, 0.0f);
    EXPECT_EQ(offset.z, 0.0f);
    CommandStack stack;
    stack.execute(doc, duplicateObject(doc, kBall, offset));
    const std::optional<WorldBox> copy = selectionBounds(doc.scene, 4, -1);
    ASSERT_TRUE(copy.has_value());
    EXPECT_LT(copy->hi.x, box->lo.x) << "the copy's box clears the original's";
    EXPECT_NEAR(copy->lo.y, box->lo.y, 1e-5f);
    EXPECT_NEAR(doc.scene.objects[4].transform.translate.x,
                doc.scene.objects[kBall].transform.translate.x + offset.x, 1e-5f)
        << "saved where it is seen";
    // Left of the middle: to the right.
    doc.scene.camera.position = {4, 0, 10};
    doc.scene.camera.lookAt = {4, 0, 0};
    EXPECT_NEAR(duplicateOffset(doc.scene, kBall).x, 1.1f * (box->hi.x - box->lo.x), 1e-5f);
}

TEST(ObjectEdits, ADuplicatesLightsMoveWithIt) {
    Document doc = fileDocument();
    const size_t lights = doc.scene.lights.size();
    const Vec3 offset{0, 0, 3};
    CommandStack stack;
    stack.execute(doc, duplicateObject(doc, kLamps, offset));
    std::vector<Vec3> original, copied;
    for (const Light& light : doc.scene.lights) {
        if (light.object == kLamps) original.push_back(light.position);
        if (light.object == 4) copied.push_back(light.position);
    }
    ASSERT_EQ(doc.scene.lights.size(), lights + 3);
    ASSERT_EQ(copied.size(), original.size());
    for (size_t i = 0; i < copied.size(); ++i) {
        EXPECT_NEAR(copied[i].z, original[i].z + 3.0f, 1e-5f);
        EXPECT_EQ(copied[i].x, original[i].x);
    }
}

TEST(ObjectEdits, RenameLight) {
    Document doc = fileDocument();
    checkEdit(doc, renameLight(doc, 0, "fill"), SceneChanges::None,
              [](Scene& s) { s.lights[0].name = "fill"; });
}

TEST(ObjectEdits, DeleteLight) {
    Document doc = fileDocument();
    EXPECT_EQ(deleteLight(doc, 0)->label(), "Delete key");
    checkEdit(doc, deleteLight(doc, 1), SceneChanges::Lights,
              [](Scene& s) { s.lights.erase(s.lights.begin() + 1); });
}

TEST(ObjectEdits, DuplicateAFileLightMakesASceneLight) {
    Document doc = fileDocument();
    size_t fileLight = 0;
    while (fileLight < doc.scene.lights.size() && doc.scene.lights[fileLight].object != kLamps) ++fileLight;
    ASSERT_LT(fileLight, doc.scene.lights.size());
    // BUG (editor/object_edits.cpp, duplicateLight): the label argument reads
    // after.lights.at(light) in the same call that moves `after` into layoutCommand's by-value
    // parameter; g++ initialises that parameter first, so the lights are already gone and .at()
    // throws std::out_of_range: duplicating any light throws.
    std::unique_ptr<EditCommand> command;
    ASSERT_NO_THROW(command = duplicateLight(doc, uint32_t(fileLight)));
    EXPECT_EQ(command->label(), "Duplicate " + doc.scene.lights[fileLight].name);
    checkEdit(doc, std::move(command), SceneChanges::Lights, [&](Scene& s) {
        Light copy = s.lights[fileLight];
        copy.name += " copy";
        copy.object = -1;
        s.lights.push_back(copy);
    });
}

// A glTF's material variants (variants.gltf: "Leather", "Linen", "variant 2"), switched from
// the Inspector: every instance of the object takes the variant's materials, the object records
// the choice for saving, and the backend is told to rebuild its instance and light tables (the
// third variant makes the frame emit).
TEST(ObjectEdits, ChoosingAMaterialVariantSwitchesEveryInstanceOfTheObject) {
    Document doc;
    doc.scene = test::loadSceneOrFail(test::writeFile(test::testFolder(), "scene.json",
                                                      R"({"version": 1,
        "objects": [{"name": "chairs", "file": ")" + test::testDataPath("gltf/variants.gltf") +
                                                          R"("}]})"));
    const auto show = [](int32_t variant) {
        return [variant](Scene& s) {
            s.objects[0].variant = variant;
            for (Instance& instance : s.instances) {
                if (instance.variantMaterials.empty()) continue;
                instance.materials =
                    variant < 0 ? instance.defaultMaterials : instance.variantMaterials[size_t(variant)];
            }
        };
    };
    const SceneDelta changes = SceneChanges::Transforms | SceneChanges::Lights;
    EXPECT_EQ(setObjectVariant(doc, 0, 1)->label(), "Variant Linen of chairs");
    checkEdit(doc, setObjectVariant(doc, 0, 1), changes, show(1));
    EXPECT_EQ(doc.scene.materials[doc.scene.instances[0].materials[0]].name, "linen");
    EXPECT_FALSE(sceneHasEmitters(doc.scene));
    checkEdit(doc, setObjectVariant(doc, 0, 2), changes, show(2));
    EXPECT_TRUE(sceneHasEmitters(doc.scene)) << "the glow variant's frame emits";
    EXPECT_EQ(setObjectVariant(doc, 0, -1)->label(), "Variant default materials of chairs");
    checkEdit(doc, setObjectVariant(doc, 0, -1), changes, show(-1));
    EXPECT_EQ(doc.scene.materials[doc.scene.instances[0].materials[0]].name, "seat");
}

}  // namespace
}  // namespace pt::editor
