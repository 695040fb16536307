// EXT_meshopt_compression (assets/gltf_meshopt.h): a tent encoded here with meshoptimizer's own
// encoders (positions as plain floats, normals as 8-bit octahedral vectors, UVs through the
// exponential filter, triangles through the index codec), its views on a fallback buffer with
// no bytes, imports with its geometry; damaged or ill-formed compressed views are errors that
// name the view; a build without libmeshoptimizer skips with a message.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "assets/draco_fixture/tent.h"
#include "assets/input_error.h"
#include "assets/model_import.h"
#include "assets/scene_test_helpers.h"
#include "support/input_error_of.h"
#if PT_TEST_HAVE_MESHOPT
#include <meshoptimizer.h>
#endif

namespace pt {
namespace {

#if PT_TEST_HAVE_MESHOPT

using test::TentCorner;

// The tent's normals leaning out from its middle, so that the octahedral filter has something
// to get right.
Vec3 leaningNormal(const TentCorner& c) { return normalize(Vec3(c.p[0] - 0.5f, c.p[1] - 0.5f, 1.0f)); }

struct Stream {
    std::string compressed;
    size_t count = 0, stride = 0;
    std::string mode, filter;
};

Stream vertexStream(const void* data, size_t count, size_t stride, const char* filter) {
    std::string out(meshopt_encodeVertexBufferBound(count, stride), '\0');
    out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(&out[0]), out.size(), data, count,
                                          stride));
    return {out, count, stride, "ATTRIBUTES", filter};
}

std::vector<Stream> tentStreams() {
    const std::vector<TentCorner> corners = test::tentCorners();
    const size_t n = corners.size();
    std::vector<float> positions, normals, uvs;
    for (const TentCorner& c : corners) {
        positions.insert(positions.end(), c.p, c.p + 3);
        const Vec3 normal = leaningNormal(c);
        normals.insert(normals.end(), {normal.x, normal.y, normal.z, 0.0f});
        uvs.insert(uvs.end(), c.uv, c.uv + 2);
    }
    std::vector<int8_t> octahedral(4 * n);
    meshopt_encodeFilterOct(octahedral.data(), n, 4, 8, normals.data());
    std::vector<uint32_t> exponential(2 * n);
    meshopt_encodeFilterExp(exponential.data(), n, 8, 15, uvs.data());
    std::vector<uint32_t> triangles(n);
    for (uint32_t i = 0; i < n; ++i) triangles[i] = i;
    std::string indices(meshopt_encodeIndexBufferBound(n, n), '\0');
    indices.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(&indices[0]), indices.size(),
                                             triangles.data(), n));
    return {
        vertexStream(positions.data(), n, 12, "NONE"), vertexStream(octahedral.data(), n, 4, "OCTAHEDRAL"),
        vertexStream(exponential.data(), n, 8, "EXPONENTIAL"), Stream{indices, n, 4, "TRIANGLES", "NONE"}};
}

// The glTF: compressed streams one after another in meshopt.bin (buffer 0), each view's
// uncompressed place on buffer 1, a fallback with no bytes. `edit` may damage one view.
std::string tentGltf(std::vector<Stream> streams, const std::string& viewOverride = "") {
    const std::string folder = test::testFolder();
    std::string bin, views;
    size_t fallbackOffset = 0;
    for (size_t i = 0; i < streams.size(); ++i) {
        const Stream& s = streams[i];
        const size_t raw = s.count * s.stride;
        std::string meshopt = R"({"buffer": 0, "byteOffset": )" + std::to_string(bin.size()) +
                              R"(, "byteLength": )" + std::to_string(s.compressed.size()) +
                              R"(, "byteStride": )" + std::to_string(s.stride) + R"(, "count": )" +
                              std::to_string(s.count) + R"(, "mode": ")" + s.mode + R"(", "filter": ")" +
                              s.filter + R"("})";
        if (i == 0 && !viewOverride.empty()) meshopt = viewOverride;
        views += std::string(i ? ", " : "") + R"({"buffer": 1, "byteOffset": )" +
                 std::to_string(fallbackOffset) + R"(, "byteLength": )" + std::to_string(raw) +
                 (s.mode == "ATTRIBUTES" ? R"(, "byteStride": )" + std::to_string(s.stride) : std::string()) +
                 R"(, "extensions": {"EXT_meshopt_compression": )" + meshopt + "}}";
        bin += s.compressed;
        while (bin.size() % 4) bin += '\0';
        fallbackOffset += raw;
    }
    test::writeFile(folder, "meshopt.bin", bin);
    const std::string n = std::to_string(streams[0].count);
    return test::writeFile(folder, "tent.gltf",
                           R"({"asset": {"version": "2.0"},
  "extensionsUsed": ["EXT_meshopt_compression", "KHR_mesh_quantization"],
  "extensionsRequired": ["EXT_meshopt_compression", "KHR_mesh_quantization"],
  "buffers": [{"uri": "meshopt.bin", "byteLength": )" +
                               std::to_string(bin.size()) + R"(},
              {"byteLength": )" +
                               std::to_string(fallbackOffset) +
                               R"(, "extensions": {"EXT_meshopt_compression": {"fallback": true}}}],
  "bufferViews": [)" + views + R"(],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": )" +
                               n + R"(, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0.4]},
    {"bufferView": 1, "componentType": 5120, "normalized": true, "count": )" +
                               n + R"(, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": )" +
                               n + R"(, "type": "VEC2"},
    {"bufferView": 3, "componentType": 5125, "count": )" +
                               n + R"(, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})");
}

TEST(GltfMeshopt, ACompressedTentImportsWithItsGeometry) {
    Scene scene;
    importGltf(tentGltf(tentStreams()), 0, scene);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    const std::vector<TentCorner> corners = test::tentCorners();
    ASSERT_EQ(mesh.indices.size(), corners.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (size_t i = 0; i < corners.size(); ++i) {
        const uint32_t v = mesh.indices[i];
        const TentCorner& c = corners[i];
        EXPECT_EQ(mesh.positions[v], Vec3(c.p[0], c.p[1], c.p[2])) << "the vertex codec is lossless";
        const Vec3 expected = leaningNormal(c);
        EXPECT_GT(dot(mesh.normals[v], expected), 0.999f) << "octahedral normal " << i;
        EXPECT_NEAR(mesh.uvs[v].x, c.uv[0], 1e-4f) << "exponential-filtered UV " << i;
        EXPECT_NEAR(mesh.uvs[v].y, c.uv[1], 1e-4f);
    }
    for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("not supported"), std::string::npos) << w;
}

std::string importError(const std::string& path) {
    Scene scene;
    return test::inputErrorOf([&] { importGltf(path, 0, scene); });
}

TEST(GltfMeshopt, DamagedOrIllFormedViewsNameTheView) {
    std::vector<Stream> damaged = tentStreams();
    for (size_t i = 1; i < damaged[0].compressed.size(); i += 3) damaged[0].compressed[i] = char(0xFF);
    const std::string view = "tent.gltf: bufferViews[0].extensions.EXT_meshopt_compression";
    std::string message = importError(tentGltf(damaged));
    EXPECT_NE(message.find(view + ": the compressed data cannot be decoded"), std::string::npos) << message;

    const std::vector<Stream> good = tentStreams();
    message = importError(tentGltf(
        good,
        R"({"buffer": 0, "byteOffset": 4000, "byteLength": 8, "byteStride": 12, "count": 12, "mode": "ATTRIBUTES"})"));
    EXPECT_NE(message.find(view + ": bytes [4000, 4008) run past the end of buffer 0"), std::string::npos)
        << message;
    message = importError(tentGltf(
        good, R"({"buffer": 0, "byteLength": 8, "byteStride": 6, "count": 12, "mode": "ATTRIBUTES"})"));
    EXPECT_NE(message.find(view + ".byteStride: 6 is not allowed in mode ATTRIBUTES"), std::string::npos)
        << message;
    message = importError(tentGltf(
        good,
        R"({"buffer": 0, "byteLength": 8, "byteStride": 12, "count": 12, "mode": "ATTRIBUTES", "filter": "QUATERNION"})"));
    EXPECT_NE(message.find(view + ".filter: 'QUATERNION' does not apply"), std::string::npos) << message;
    message = importError(tentGltf(
        good,
        R"({"buffer": 0, "byteLength": 8, "byteStride": 12, "count": 600000000, "mode": "ATTRIBUTES"})"));
    EXPECT_NE(message.find("too large to decode"), std::string::npos) << message;
}

#else

TEST(GltfMeshopt, NeedsLibmeshoptimizer) {
    GTEST_SKIP() << "this build has no libmeshoptimizer (install libmeshoptimizer-dev)";
}

#endif

}  // namespace
}  // namespace pt
