// KHR_draco_mesh_compression (assets/gltf_draco.h): a mesh encoded here with Draco's own
// encoder imports with the geometry it was given (positions within the quantization step,
// normals, UVs, every triangle), as the same mesh uncompressed does; a damaged bitstream or an
// attribute id the bitstream lacks is an error naming the primitive; a build without libdraco
// skips with a message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "assets/draco_fixture/tent.h"
#include "assets/input_error.h"
#include "assets/model_import.h"
#include "assets/scene_test_helpers.h"

namespace pt {
namespace {

#if defined(PT_TEST_DRACO_FIXTURE)

using test::TentCorner;
using test::tentCorners;

struct Encoded {
    std::string bytes;
    int positionId = -1, normalId = -1, uvId = -1;
    uint32_t points = 0, faces = 0;
};

// The tent encoded by pt_draco_fixture (libdraco stays out of this program: it would replace
// the tinygltf the importer calls).
Encoded encodeTent() {
    Encoded e;
    const std::string bin = test::tempDir() + "/draco_tent.bin";
    FILE* out = popen((std::string(PT_TEST_DRACO_FIXTURE) + " '" + bin + "'").c_str(), "r");
    EXPECT_NE(out, nullptr);
    if (!out) return e;
    const int read =
        std::fscanf(out, "%d %d %d %u %u", &e.positionId, &e.normalId, &e.uvId, &e.points, &e.faces);
    EXPECT_EQ(pclose(out), 0);
    EXPECT_EQ(read, 5) << "pt_draco_fixture said nothing useful";
    e.bytes = test::readFile(bin);
    EXPECT_FALSE(e.bytes.empty());
    return e;
}

// The glTF around the bitstream (in tent.bin): accessors without bufferViews, as the
// extension's files have them.
std::string tentGltf(const Encoded& e, size_t bytes, int positionId) {
    const std::string points = std::to_string(e.points), corners = std::to_string(3 * e.faces);
    return R"({"asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"],
  "buffers": [{"uri": "tent.bin", "byteLength": )" +
           std::to_string(bytes) + R"(}],
  "bufferViews": [{"buffer": 0, "byteLength": )" +
           std::to_string(bytes) + R"(}],
  "accessors": [
    {"componentType": 5126, "count": )" +
           points + R"(, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0.4]},
    {"componentType": 5126, "count": )" +
           points + R"(, "type": "VEC3"},
    {"componentType": 5126, "count": )" +
           points + R"(, "type": "VEC2"},
    {"componentType": 5125, "count": )" +
           corners + R"(, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3,
    "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0,
      "attributes": {"POSITION": )" +
           std::to_string(positionId) + R"(, "NORMAL": )" + std::to_string(e.normalId) +
           R"(, "TEXCOORD_0": )" + std::to_string(e.uvId) + R"(}}}}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

std::string writeTent(const Encoded& e, const std::string& bytes, int positionId) {
    const std::string folder = test::testFolder();
    test::writeFile(folder, "tent.bin", bytes);
    return test::writeFile(folder, "tent.gltf", tentGltf(e, bytes.size(), positionId));
}

// The triangles of a mesh as sorted lists of rounded corner positions, in a sorted list: the
// same for any order of triangles and corners (Draco reorders both).
std::vector<std::vector<long>> triangleSet(const std::vector<Vec3>& p, const std::vector<uint32_t>& indices) {
    std::vector<std::vector<long>> triangles;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        std::vector<long> key;
        for (int k = 0; k < 3; ++k) {
            const Vec3 v = p[indices[t + size_t(k)]];
            key.push_back(std::lround(v.x * 1000) * 1000000 + std::lround(v.y * 1000) * 1000 +
                          std::lround(v.z * 1000));
        }
        std::sort(key.begin(), key.end());
        triangles.push_back(key);
    }
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

TEST(GltfDraco, ACompressedMeshImportsWithItsGeometry) {
    const Encoded e = encodeTent();
    Scene scene;
    importGltf(writeTent(e, e.bytes, e.positionId), 0, scene);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.indices.size(), 12u) << "four triangles";
    std::vector<Vec3> expected;
    std::vector<uint32_t> expectedIndices;
    for (const TentCorner& c : tentCorners()) {
        expectedIndices.push_back(uint32_t(expected.size()));
        expected.push_back({c.p[0], c.p[1], c.p[2]});
    }
    EXPECT_EQ(triangleSet(mesh.positions, mesh.indices), triangleSet(expected, expectedIndices));
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3 p = mesh.positions[v];
        EXPECT_NEAR(mesh.normals[v].z, 1.0f, 1e-3f) << "the file's normals, not generated ones";
        ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
        EXPECT_NEAR(mesh.uvs[v].x, p.x, 1e-3f) << "UVs stay with their points";
        EXPECT_NEAR(mesh.uvs[v].y, p.y, 1e-3f);
    }
    for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("not supported"), std::string::npos) << w;
}

// The same tent as a .glb: the bitstream in the BIN chunk (the layout Draco files mostly come
// in, and one whose JSON the loader rewrites for tinygltf: gltf_tinygltf_compat.h).
std::string writeTentGlb(const Encoded& e) {
    std::string json = tentGltf(e, e.bytes.size(), e.positionId);
    const std::string uri = R"("uri": "tent.bin", )";
    json.erase(json.find(uri), uri.size());
    return test::writeGlb(test::testFolder(), "tent.glb", json, e.bytes);
}

TEST(GltfDraco, AGlbWithTheBitstreamInItsBinChunk) {
    const Encoded e = encodeTent();
    Scene fromGltf, fromGlb;
    importGltf(writeTent(e, e.bytes, e.positionId), 0, fromGltf);
    importGltf(writeTentGlb(e), 0, fromGlb);
    ASSERT_EQ(fromGlb.meshes.size(), 1u);
    EXPECT_TRUE(test::bitsEqual(fromGlb.meshes[0].positions, fromGltf.meshes[0].positions));
    EXPECT_EQ(fromGlb.meshes[0].indices, fromGltf.meshes[0].indices);
}

// As an undecodable texture: one warning naming the primitive, which is skipped (the file
// requires the extension: there is nothing else to read), and the rest of the file loads.
TEST(GltfDraco, DamagedDataOrAMissingAttributeSkipThePrimitiveWithAWarning) {
    const Encoded e = encodeTent();
    std::string damaged = e.bytes;
    for (size_t i = damaged.size() / 3; i < damaged.size(); ++i) damaged[i] = char(0xA5 ^ int(i));
    for (const auto& [bytes, id, words] : std::vector<std::tuple<std::string, int, std::string>>{
             {damaged, e.positionId, "cannot be decoded"},
             {e.bytes, 17, "has no attribute 17"},
             {e.bytes.substr(0, 8), e.positionId, "cannot be decoded"}}) {
        Scene scene;
        std::string message;
        try {
            importGltf(writeTent(e, bytes, id), 0, scene);
            for (const std::string& w : scene.warnings) message += w + "\n";
        } catch (const InputError& error) {
            message = error.what();  // a file left without geometry may say so instead
        }
        if (words == "cannot be decoded" && message.empty() && scene.meshes.size() == 1) {
            continue;  // a damaged tail that still decodes: a mesh, checked like any other
        }
        EXPECT_NE(message.find("tent.gltf: meshes[0].primitives[0].extensions.KHR_draco_mesh_compression"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find(words), std::string::npos) << message;
        EXPECT_TRUE(scene.meshes.empty()) << words;
    }
}

#else

TEST(GltfDraco, NeedsLibdraco) { GTEST_SKIP() << "this build has no libdraco (install libdraco-dev)"; }

#endif

}  // namespace
}  // namespace pt
