// A .glb's BIN chunk read where it lies in the mapped file (assets/gltf/gltf_glb_bin.h):
// the JSON rewritten for tinygltf and put back, and a textured .glb importing as the same scene
// as its .gltf twin.
#include "assets/gltf/gltf_glb_bin.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "assets/gltf/gltf_document.h"
#include "assets/model_import.h"
#include "assets/scene_test_helpers.h"
#include "support/test_paths.h"

namespace pt {
namespace {

nlohmann::json glbJson() {
    return nlohmann::json::parse(R"({
      "buffers": [{"byteLength": 10}, {"byteLength": 4, "uri": "other.bin"}],
      "images": [{"bufferView": 1, "mimeType": "image/png", "width": 2},
                 {"uri": "file.png"},
                 {"bufferView": 2, "uri": "both.png"}]})");
}

TEST(GltfGlbBin, TinygltfIsGivenStandInsAndTheModelGetsTheChunkAndTheViewsBack) {
    nlohmann::json root = glbJson();
    const std::optional<DetachedGlbBin> detached = detachGlbBin(root);
    ASSERT_TRUE(detached);
    EXPECT_EQ(detached->byteLength, 10u);
    // Buffer 0 and the image in a view stand in as data URIs tinygltf reads without the chunk.
    EXPECT_EQ(root["buffers"][0]["byteLength"], 4);
    EXPECT_EQ(root["buffers"][0]["uri"].get<std::string>().rfind("data:", 0), 0u);
    EXPECT_EQ(root["buffers"][1]["uri"], "other.bin");
    EXPECT_FALSE(root["images"][0].contains("bufferView"));
    EXPECT_EQ(root["images"][0]["uri"].get<std::string>().rfind("data:", 0), 0u);
    EXPECT_EQ(root["images"][1]["uri"], "file.png");
    // Both a view and a uri: left for tinygltf to reject, as before.
    EXPECT_EQ(root["images"][2]["bufferView"], 2);
    ASSERT_EQ(detached->imageViews.size(), 1u);

    // tinygltf's model as the stand-ins leave it: the data URI's bytes kept and its mime type.
    tinygltf::Model model;
    model.buffers.resize(2);
    model.buffers[0].uri = root["buffers"][0]["uri"];
    model.buffers[0].data = {0, 0, 0, 0};
    model.images.resize(3);
    model.images[0].uri = root["images"][0]["uri"];
    model.images[0].image = {0, 0, 0, 0};
    model.images[0].as_is = true;
    model.images[0].mimeType = "application/octet-stream";
    attachGlbBin(model, *detached);
    EXPECT_TRUE(model.buffers[0].data.empty()) << "the stand-in's bytes: the import reads the chunk";
    EXPECT_TRUE(model.buffers[0].uri.empty());
    const tinygltf::Image& image = model.images[0];
    EXPECT_EQ(image.bufferView, 1);
    EXPECT_EQ(image.mimeType, "image/png");
    EXPECT_EQ(image.width, 2);
    EXPECT_EQ(image.height, 0);
    EXPECT_TRUE(image.uri.empty());
    EXPECT_TRUE(image.image.empty());
    EXPECT_FALSE(image.as_is);
}

TEST(GltfGlbBin, LeftToTinygltfWhereAnotherBufferHasNoUriOrBufferZeroHasOne) {
    nlohmann::json twoWithout = glbJson();
    twoWithout["buffers"][1].erase("uri");
    const nlohmann::json before = twoWithout;
    EXPECT_FALSE(detachGlbBin(twoWithout));
    EXPECT_EQ(twoWithout, before) << "unchanged";

    nlohmann::json external = glbJson();
    external["buffers"][0]["uri"] = "zero.bin";
    EXPECT_FALSE(detachGlbBin(external));
    nlohmann::json noBuffers = nlohmann::json::object();
    EXPECT_FALSE(detachGlbBin(noBuffers));
}

// A unit quad with a PNG base colour texture: positions, normals, UVs and indices, then the PNG
// file's bytes, in one buffer.
struct TexturedQuad {
    std::string bin, png;
    std::string json(const std::string& bufferUri, const std::string& imageSource) const {
        const size_t geometry = bin.size() - png.size();
        return R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": )" +
               std::to_string(bin.size()) + bufferUri + R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 12},
                  {"buffer": 0, "byteOffset": )" +
               std::to_string(geometry) + R"(, "byteLength": )" + std::to_string(png.size()) + R"(}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "images": [)" +
               imageSource +
               R"(], "textures": [{"source": 0}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    }
};

TexturedQuad texturedQuad() {
    TexturedQuad quad;
    const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const float uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};
    const uint16_t indices[] = {0, 1, 2, 0, 2, 3, 0, 0};  // 12 bytes used, 4 of padding
    for (const auto& [data, bytes] : {std::pair<const void*, size_t>{positions, sizeof(positions)},
                                      {normals, sizeof(normals)},
                                      {uvs, sizeof(uvs)},
                                      {indices, sizeof(indices)}}) {
        quad.bin.append(static_cast<const char*>(data), bytes);
    }
    quad.png = test::readFile(test::testDataPath("gltf/checker.png"));
    quad.bin += quad.png;
    return quad;
}

TEST(GltfGlbBin, ATexturedGlbImportsAsItsGltfTwin) {
    const TexturedQuad quad = texturedQuad();
    const std::string folder = test::testFolder();
    test::writeFile(folder, "quad.bin", quad.bin);
    // The twin's image is the same bytes through a view of its external buffer: the texture's
    // source path stays empty in both, so the scenes compare whole.
    const std::string imageInView = R"({"bufferView": 4, "mimeType": "image/png"})";
    const std::string gltf =
        test::writeFile(folder, "quad.gltf", quad.json(R"(, "uri": "quad.bin")", imageInView));
    const std::string glb = test::writeGlb(folder, "quad.glb", quad.json("", imageInView), quad.bin);
    const GltfDocument doc = loadGltfDocument(glb);
    ASSERT_EQ(doc.mappedBuffers.count(0), 1u);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(doc.mappedBuffers.at(0).data),
                          doc.mappedBuffers.at(0).count),
              quad.bin)
        << "buffer 0 is the BIN chunk where it lies in the mapped file";
    Scene fromGltf, fromGlb;
    importGltf(gltf, 0, fromGltf);
    importGltf(glb, 0, fromGlb);
    ASSERT_EQ(fromGlb.textures.size(), 1u);
    EXPECT_FALSE(fromGlb.textures[0].texels8.empty()) << "the PNG in the BIN chunk decoded";
    EXPECT_TRUE(fromGlb.warnings.empty()) << fromGlb.warnings.front();
    EXPECT_TRUE(test::scenesEqual(fromGltf, fromGlb));
}

}  // namespace
}  // namespace pt
