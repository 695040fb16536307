// A .gltf's external buffer files mapped, not read (assets/gltf/gltf_external_buffers.h): the
// JSON tinygltf is given, and a mesh read through the mapping importing as its .glb twin.
#include "assets/gltf/gltf_external_buffers.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "assets/gltf/gltf_document.h"
#include "assets/model_import.h"
#include "assets/scene_test_helpers.h"
#include "support/test_paths.h"

namespace pt {
namespace {

TEST(GltfExternalBuffers, FileBuffersStandInAndTheRestAreTinygltfs) {
    nlohmann::json root = nlohmann::json::parse(R"({
      "buffers": [{"byteLength": 12, "uri": "a%20b.bin"},
                  {"byteLength": 4, "uri": "data:application/octet-stream;base64,AAAAAA=="},
                  {"byteLength": 8},
                  {"byteLength": 20, "uri": "images.bin"}],
      "bufferViews": [{"buffer": 0, "byteLength": 12}, {"buffer": 3, "byteLength": 20}],
      "images": [{"bufferView": 1, "mimeType": "image/png"}]})");
    const nlohmann::json before = root;
    const std::vector<ExternalBufferFile> files = detachExternalBuffers(root, "folder");
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].buffer, 0);
    EXPECT_EQ(files[0].path, "folder/a b.bin") << "the uri decoded, under the glTF's folder";
    EXPECT_EQ(root["buffers"][0]["byteLength"], 4);
    EXPECT_EQ(root["buffers"][0]["uri"].get<std::string>().rfind("data:", 0), 0u);
    EXPECT_EQ(root["buffers"][1], before["buffers"][1]) << "a data URI is tinygltf's to decode";
    EXPECT_EQ(root["buffers"][2], before["buffers"][2]);
    EXPECT_EQ(root["buffers"][3], before["buffers"][3]) << "tinygltf reads its image while it parses";
}

TEST(GltfExternalBuffers, AMeshReadThroughTheMappingImportsAsItsGlbTwin) {
    const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const uint16_t indices[] = {0, 1, 2, 0, 2, 3, 0, 0};  // 12 bytes used, 4 of padding
    std::string bin(reinterpret_cast<const char*>(positions), sizeof(positions));
    bin.append(reinterpret_cast<const char*>(indices), sizeof(indices));
    const auto json = [&](const std::string& bufferUri) {
        return R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": )" +
               std::to_string(bin.size()) + bufferUri + R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    };
    const std::string folder = test::testFolder();
    test::writeFile(folder, "quad.bin", bin);
    const std::string gltf = test::writeFile(folder, "quad.gltf", json(R"(, "uri": "quad.bin")"));
    const std::string glb = test::writeGlb(folder, "quad.glb", json(""), bin);

    const GltfDocument doc = loadGltfDocument(gltf);
    ASSERT_EQ(doc.mappedBuffers.count(0), 1u);
    EXPECT_EQ(doc.mappedBuffers.at(0).count, bin.size());
    EXPECT_EQ(doc.model.buffers[0].data.size(), 4u) << "tinygltf holds the stand-in, not the file";

    Scene fromGltf, fromGlb;
    importGltf(gltf, 0, fromGltf);
    importGltf(glb, 0, fromGlb);
    ASSERT_EQ(fromGltf.meshes.size(), 1u);
    EXPECT_EQ(fromGltf.meshes[0].primitiveCount(), 2u) << "both triangles read from the mapped file";
    EXPECT_TRUE(test::scenesEqual(fromGltf, fromGlb));
}

}  // namespace
}  // namespace pt
