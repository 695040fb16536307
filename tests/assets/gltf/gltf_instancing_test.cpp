// EXT_mesh_gpu_instancing (assets/gltf_instancing.h): a node's mesh placed once per instance,
// each instance's TRS under the node's transform; float and normalized-integer rotations;
// attribute counts that disagree are an error naming the attribute; zero-scale instances are
// left out with one warning.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "assets/input_error.h"
#include "assets/model_import.h"
#include "support/test_paths.h"

namespace pt {
namespace {

std::string bytesOf(const std::vector<float>& floats) {
    std::string bytes(floats.size() * 4, '\0');
    std::memcpy(bytes.data(), floats.data(), bytes.size());
    return bytes;
}

// A triangle (POSITION: accessor 0) on a node translated by (0, 0, 10) and scaled by 2,
// instanced by `attributes`: accessors 1.. (JSON `accessors`) over bufferView 1, whose bytes are
// `instanceBytes`.
std::string instancedGltf(const std::string& name, const std::string& instanceBytes,
                          const std::string& accessors, const std::string& attributes) {
    const std::string triangle = bytesOf({0, 0, 0, 1, 0, 0, 0, 1, 0});
    test::writeTempFile(name + ".bin", triangle + instanceBytes);
    const std::string json = R"({"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_mesh_gpu_instancing"],
      "buffers": [{"byteLength": )" +
                             std::to_string(36 + instanceBytes.size()) + R"(, "uri": ")" + name + R"(.bin"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36},
                      {"buffer": 0, "byteOffset": 36, "byteLength": )" +
                             std::to_string(instanceBytes.size()) + R"(}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                     "min": [0, 0, 0], "max": [1, 1, 0]}, )" +
                             accessors + R"(],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "nodes": [{"name": "grove", "mesh": 0, "translation": [0, 0, 10], "scale": [2, 2, 2],
                 "extensions": {"EXT_mesh_gpu_instancing": {"attributes": )" +
                             attributes + R"(}}}],
      "scenes": [{"nodes": [0]}], "scene": 0})";
    return test::writeTempFile(name + ".gltf", json);
}

void expectNear(Vec3 a, Vec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(GltfInstancing, EachInstanceIsPlacedUnderTheNode) {
    // Three instances: translations, rotations (identity; 90 degrees about Z; unnormalised 180
    // about Y) and scales.
    const std::vector<float> data = {1, 0, 0, 0, 2, 0, 0,          0,          3,           // TRANSLATION
                                     0, 0, 0, 1, 0, 0, 0.7071068f, 0.7071068f, 0, 2, 0, 0,  // ROTATION
                                     1, 1, 1, 1, 1, 1, 3,          3,          3};          // SCALE
    const std::string accessors =
        R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
           {"bufferView": 1, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC4"},
           {"bufferView": 1, "byteOffset": 84, "componentType": 5126, "count": 3, "type": "VEC3"})";
    Scene scene;
    const ImportedFile file = importGltf(
        instancedGltf("grove", bytesOf(data), accessors, R"({"TRANSLATION": 1, "ROTATION": 2, "SCALE": 3})"),
        0, scene);
    ASSERT_EQ(file.placements.size(), 3u);
    EXPECT_EQ(scene.meshes.size(), 1u) << "one mesh, placed three times";
    EXPECT_EQ(file.placements[1].name, "grove #1");
    // world = node (translate z 10, scale 2) * instance (T R S).
    expectNear(file.placements[0].fileToNode.transformPoint({1, 0, 0}), {4, 0, 10});
    expectNear(file.placements[1].fileToNode.transformPoint({1, 0, 0}), {0, 6, 10});   // (0,1,0)+(0,2,0), x2
    expectNear(file.placements[2].fileToNode.transformPoint({1, 0, 0}), {-6, 0, 16});  // (-3,0,0)+(0,0,3), x2
    bool warnedExtension = false;
    for (const std::string& w : scene.warnings)
        warnedExtension |= w.find("EXT_mesh_gpu_instancing") != std::string::npos;
    EXPECT_FALSE(warnedExtension) << "honoured, not warned about";
    EXPECT_TRUE(scene.gltfExtensions.at("EXT_mesh_gpu_instancing"));
}

// Rotations as normalized shorts (the extension allows them), and one instance of zero scale.
TEST(GltfInstancing, NormalizedRotationsAndHiddenInstances) {
    std::string bytes;
    const int16_t rotation[8] = {0, 0, 0, 32767, 0, 0, 23170, 23170};  // identity; 90 about Z
    bytes.append(reinterpret_cast<const char*>(rotation), sizeof rotation);
    bytes += bytesOf({1, 1, 1, 0, 0, 0});  // SCALE: the second instance hidden
    const std::string accessors =
        R"({"bufferView": 1, "componentType": 5122, "normalized": true, "count": 2, "type": "VEC4"},
           {"bufferView": 1, "byteOffset": 16, "componentType": 5126, "count": 2, "type": "VEC3"})";
    Scene scene;
    const ImportedFile file =
        importGltf(instancedGltf("shorts", bytes, accessors, R"({"ROTATION": 1, "SCALE": 2})"), 0, scene);
    ASSERT_EQ(file.placements.size(), 1u);
    expectNear(file.placements[0].fileToNode.transformPoint({1, 0, 0}), {2, 0, 10});
    size_t warnings = 0;
    for (const std::string& w : scene.warnings)
        warnings += w.find("1 of 2 EXT_mesh_gpu_instancing") != std::string::npos;
    EXPECT_EQ(warnings, 1u);

    // The rotation of the one instance left, decoded from shorts.
    Scene turned;
    const std::string turnedAccessors =
        R"({"bufferView": 1, "byteOffset": 8, "componentType": 5122, "normalized": true, "count": 1, "type": "VEC4"})";
    const ImportedFile one =
        importGltf(instancedGltf("turned", bytes, turnedAccessors, R"({"ROTATION": 1})"), 0, turned);
    ASSERT_EQ(one.placements.size(), 1u);
    expectNear(one.placements[0].fileToNode.transformPoint({1, 0, 0}), {0, 2, 10});
}

TEST(GltfInstancing, AttributeCountsThatDisagreeAreAnErrorNamingTheAttribute) {
    const std::vector<float> data = {0, 0, 0, 1, 1, 1, 1, 1, 1, 2, 2, 2};
    const std::string accessors =
        R"({"bufferView": 1, "componentType": 5126, "count": 1, "type": "VEC3"},
           {"bufferView": 1, "byteOffset": 12, "componentType": 5126, "count": 2, "type": "VEC3"})";
    Scene scene;
    try {
        importGltf(instancedGltf("mismatch", bytesOf(data), accessors, R"({"TRANSLATION": 1, "SCALE": 2})"),
                   0, scene);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.SCALE"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("has 2 instances, the other attributes 1"), std::string::npos) << what;
    }
    EXPECT_THROW(importGltf(instancedGltf("none", bytesOf(data), accessors, "{}"), 0, scene), InputError);
    EXPECT_THROW(importGltf(instancedGltf("bad", bytesOf(data), accessors, R"({"SCALE": 9})"), 0, scene),
                 InputError);
}

}  // namespace
}  // namespace pt
