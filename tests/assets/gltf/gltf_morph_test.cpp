// glTF morph targets (fixtures: tests/data/gltf/morph_fixtures.py, which says what each file
// holds): base vertices, deltas through the importer's vertex remapping, names, default
// weights applied, node weights, malformed targets; and the scene JSON "morphWeights" key
// (read, override, write only changes, round trip, errors).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "assets/input_error.h"
#include "assets/model_import.h"
#include "assets/scene_json/scene_json.h"
#include "assets/scene_loader.h"
#include "assets/scene_test_helpers.h"
#include "support/load_scene.h"
#include "support/test_paths.h"

// Formatted by hand: the vertex tables are laid out by primitive.
// clang-format off
namespace pt {
namespace {

const Vec3 kZero(0.0f);

Scene importFixture(const std::string& name) {
    Scene scene;
    importGltf(test::testDataPath("gltf/" + name), 0, scene);
    return scene;
}

// --- import -------------------------------------------------------------------------------

// morph_quad.gltf, vertex by vertex: primitives[0] keeps its 4 vertices (0-3); primitives[1]
// has no normals, so its corners [0, 1, 2, 0, 2, 3] become vertices 4-9; primitives[2] is 10-12.
TEST(GltfMorph, ImportsBaseVerticesDeltasAndNames) {
    const Scene scene = importFixture("morph_quad.gltf");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    const std::vector<Vec3> base = {
        {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},                        // primitives[0]
        {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 0, 0}, {3, 1, 0}, {2, 1, 0},  // [1], unshared
        {0, 2, 0}, {1, 2, 0}, {0, 3, 0}};                                  // [2]
    EXPECT_EQ(mesh.basePositions, base);
    ASSERT_EQ(mesh.baseNormals.size(), base.size());
    for (const Vec3& n : mesh.baseNormals) EXPECT_EQ(n, Vec3(0, 0, 1));

    ASSERT_EQ(mesh.morphTargets.size(), 2u);
    const MorphTarget& lift = mesh.morphTargets[0];
    const MorphTarget& slide = mesh.morphTargets[1];
    EXPECT_EQ(lift.name, "Lift");
    EXPECT_EQ(slide.name, "Slide");
    EXPECT_EQ(lift.positionDeltas,
              (std::vector<Vec3>{kZero, kZero, {0, 0, 2}, {0, 0, 2},
                                 {0, 0, 1}, kZero, kZero, {0, 0, 1}, kZero, kZero,  // corner 0 twice
                                 kZero, kZero, kZero}));
    EXPECT_EQ(lift.normalDeltas,
              (std::vector<Vec3>{kZero, kZero, {0, -1, 0}, {0, -1, 0}, kZero, kZero, kZero, kZero,
                                 kZero, kZero, kZero, kZero, kZero}))
        << "primitives[1] has no normals to move: its NORMAL deltas are dropped";
    EXPECT_EQ(slide.positionDeltas,
              (std::vector<Vec3>{kZero, {0.5f, 0, 0}, kZero, kZero,  // from a sparse accessor
                                 kZero, kZero, kZero, kZero, kZero, {1, 0, 0}, kZero, kZero, kZero}));
    EXPECT_TRUE(slide.normalDeltas.empty());
}

TEST(GltfMorph, DefaultWeightsAreApplied) {
    const Scene scene = importFixture("morph_quad.gltf");
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.morphWeights, (std::vector<float>{0.25f, 0.0f}));
    EXPECT_EQ(mesh.defaultMorphWeights, mesh.morphWeights);
    // Lift at 0.25: vertices 2, 3 up by 0.5, vertices 4 and 7 (corner 0 of primitives[1]) by 0.25.
    const std::vector<Vec3> posed = {
        {0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}, {0, 1, 0.5f},
        {2, 0, 0.25f}, {3, 0, 0}, {3, 1, 0}, {2, 0, 0.25f}, {3, 1, 0}, {2, 1, 0},
        {0, 2, 0}, {1, 2, 0}, {0, 3, 0}};
    EXPECT_EQ(mesh.positions, posed);
    // (0, 0, 1) + 0.25 (0, -1, 0), renormalized.
    const float len = std::sqrt(1.0f + 0.0625f);
    for (size_t v : {2, 3}) {
        EXPECT_EQ(mesh.normals[v].x, 0.0f);
        EXPECT_NEAR(mesh.normals[v].y, -0.25f / len, 1e-6f);
        EXPECT_NEAR(mesh.normals[v].z, 1.0f / len, 1e-6f);
    }
    EXPECT_EQ(mesh.normals[0], Vec3(0, 0, 1));
    EXPECT_EQ(mesh.indices.size(), 3u * (2 + 2 + 1));
}

TEST(GltfMorph, FirstNodeWeightsPoseASharedMeshAndOthersAreWarnedAbout) {
    const Scene scene = importFixture("morph_nodes.gltf");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.morphTargets[0].name, "target 0");
    EXPECT_EQ(mesh.defaultMorphWeights, std::vector<float>{1.0f});
    EXPECT_EQ(mesh.morphWeights, std::vector<float>{1.0f});
    EXPECT_EQ(mesh.positions[2], Vec3(1, 1, 1));
    auto warned = [&](const std::string& text) {
        for (const std::string& w : scene.warnings) {
            if (w.find(text) != std::string::npos) return true;
        }
        return false;
    };
    EXPECT_TRUE(warned("morph_nodes.gltf: nodes[1]: morph weights differ"));
    EXPECT_TRUE(warned("morph_nodes.gltf: nodes[2]: morph weights differ"));
    EXPECT_FALSE(warned("nodes[0]"));
    EXPECT_TRUE(warned("meshes[0].primitives[0].targets[0]: morph target attribute TEXCOORD_0"));
    EXPECT_EQ(scene.warnings.size(), 3u) << scene.warnings.front();
}

TEST(GltfMorph, MalformedTargetsNameTheFileAndElement) {
    const std::pair<const char*, const char*> cases[] = {
        {"morph_bad_count.gltf",
         "morph_bad_count.gltf: meshes[0].primitives[0].targets[1]: POSITION accessor 1 has 3 "
         "elements but POSITION has 4"},
        {"morph_bad_type.gltf",
         "morph_bad_type.gltf: meshes[0].primitives[0].targets[0]: POSITION accessor 0 has 2 "
         "components per element, expected 3"},
        {"morph_nan.gltf",
         "morph_nan.gltf: meshes[0].primitives[0].targets[0]: NORMAL accessor 0 element 1 is not finite"},
        {"morph_target_mismatch.gltf",
         "morph_target_mismatch.gltf: meshes[0].primitives[1].targets: 1 morph targets, but "
         "primitives[0] has 2"},
        {"morph_bad_weights.gltf", "morph_bad_weights.gltf: meshes[0].weights: expected 2 numbers, got 3"},
        {"morph_bad_node_weights.gltf",
         "morph_bad_node_weights.gltf: nodes[0].weights: expected 1 numbers, got 2"},
    };
    for (const auto& [file, expected] : cases) {
        const LoadResult result = loadScene(test::testDataPath(std::string("gltf/") + file));
        EXPECT_FALSE(result.ok()) << file;
        EXPECT_EQ(result.error.rfind(expected, 0), 0u) << result.error;
    }
}

// --- scene JSON ----------------------------------------------------------------------------

std::string quadPath() { return test::testDataPath("gltf/morph_quad.gltf"); }

std::string sceneText(const std::string& objects) {
    return "{\"version\": 1, \"objects\": [" + objects + "]}";
}

std::string fileObject(const std::string& extra = "") {
    return "{\"file\": \"" + quadPath() + "\"" + extra + "}";
}

// The Scene mesh the object's instance uses.
const Mesh& objectMesh(const Scene& scene, int32_t object) {
    for (const Instance& instance : scene.instances) {
        if (instance.object == object) return scene.meshes.at(instance.mesh);
    }
    throw std::runtime_error("object has no instance");
}

TEST(GltfMorphSceneJson, WeightsOverrideTheFileDefaults) {
    const std::string folder = test::testFolder();
    const std::string path = test::writeFile(
        folder, "scene.json",
        sceneText(fileObject(", \"morphWeights\": {\"MorphQuad\": [1, 0.5]}") + ", " + fileObject()));
    const Scene scene = test::loadSceneOrFail(path);
    const Mesh& posed = objectMesh(scene, 0);
    EXPECT_EQ(posed.morphWeights, (std::vector<float>{1.0f, 0.5f}));
    EXPECT_EQ(posed.defaultMorphWeights, (std::vector<float>{0.25f, 0.0f}));
    EXPECT_EQ(posed.positions[1], Vec3(1.25f, 0, 0));
    EXPECT_EQ(posed.positions[2], Vec3(1, 1, 2));
    EXPECT_EQ(posed.positions[4], Vec3(2, 0, 1));
    EXPECT_EQ(posed.positions[9], Vec3(2.5f, 1, 0));
    EXPECT_EQ(scene.objects[0].morphWeights.at("MorphQuad"), (std::vector<float>{1.0f, 0.5f}));
    // A mesh holds one pose: the object without weights gets its own import of the file.
    EXPECT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(objectMesh(scene, 1).morphWeights, (std::vector<float>{0.25f, 0.0f}));
    EXPECT_TRUE(scene.objects[1].morphWeights.empty());
}

TEST(GltfMorphSceneJson, RoundTripsAndWritesOnlyChangedWeights) {
    const std::string folder = test::testFolder();
    const std::string weights = ", \"morphWeights\": {\"MorphQuad\": [-0.5, 0.1]}";
    const std::string path = test::writeFile(
        folder, "scene.json", sceneText(fileObject(weights) + ", " + fileObject() + ", " + fileObject(weights)));
    Scene scene = test::loadSceneOrFail(path);
    ASSERT_EQ(scene.meshes.size(), 2u) << "objects 0 and 2 pose the file alike and share its meshes";
    // What the editor records when a slider goes back to the file's pose: not worth saving.
    scene.objects[1].morphWeights["MorphQuad"] = {0.25f, 0.0f};

    const std::string saved = folder + "/saved.json";
    writeSceneJson(scene, saved);
    const std::string text = test::readFile(saved);
    EXPECT_NE(text.find("\"MorphQuad\": [-0.5, 0.1]"), std::string::npos) << text;
    size_t written = 0;
    for (size_t at = text.find("morphWeights"); at != std::string::npos; at = text.find("morphWeights", at + 1)) {
        ++written;
    }
    EXPECT_EQ(written, 2u) << text;

    scene.objects[1].morphWeights.clear();
    const Scene again = test::loadSceneOrFail(saved);
    EXPECT_TRUE(test::scenesEqual(scene, again));
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        EXPECT_EQ(again.objects[i].morphWeights, scene.objects[i].morphWeights) << "objects[" << i << "]";
    }
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        EXPECT_TRUE(test::bitsEqual(again.meshes[m].morphWeights, scene.meshes[m].morphWeights));
        EXPECT_TRUE(test::bitsEqual(again.meshes[m].positions, scene.meshes[m].positions));
        EXPECT_TRUE(test::bitsEqual(again.meshes[m].normals, scene.meshes[m].normals));
    }
}

TEST(GltfMorphSceneJson, BadWeightsNameTheJsonPath) {
    const std::string folder = test::testFolder();
    const std::pair<std::string, std::string> cases[] = {
        {fileObject(", \"morphWeights\": {\"Nope\": [1, 0]}"),
         "scene.json: objects[0].morphWeights.Nope: morph_quad.gltf has no mesh \"Nope\""},
        {fileObject(", \"morphWeights\": {\"MorphQuad\": [1, 0, 0]}"),
         "scene.json: objects[0].morphWeights.MorphQuad: expected 2 weights (the mesh's morph targets), got 3"},
        {fileObject(", \"morphWeights\": {\"MorphQuad\": [1, 1e39]}"),
         "scene.json: objects[0].morphWeights.MorphQuad[1]: expected a finite number"},
        {fileObject(", \"morphWeights\": {\"MorphQuad\": 1}"),
         "scene.json: objects[0].morphWeights.MorphQuad: expected an array"},
        {fileObject(", \"morphWeights\": [1]"), "scene.json: objects[0].morphWeights: expected an object"},
        {"{\"shape\": \"box\", \"morphWeights\": {}}",
         "scene.json: objects[0].morphWeights: applies to file objects"},
    };
    for (const auto& [object, expected] : cases) {
        const LoadResult result = loadScene(test::writeFile(folder, "scene.json", sceneText(object)));
        EXPECT_FALSE(result.ok()) << object;
        EXPECT_EQ(result.error.rfind(expected, 0), 0u) << result.error;
    }
}

}  // namespace
// clang-format on
}  // namespace pt
