// How the glTF importer lays a mesh's vertex arrays out: primitives that share one vertex
// accessor keep only the vertices they use, in first-use order; a primitive that uses every
// vertex keeps the file's order; packed and interleaved (byteStride) accessors, 16- and 32-bit
// indices read alike; slots are listed only for meshes of several primitives.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "assets/model_import.h"
#include "support/test_paths.h"

namespace pt {
namespace {

const std::vector<Vec3> kPositions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}};
const Vec3 kNormal(0.0f, 0.0f, 1.0f);

template <class T>
void appendBytes(std::string& bytes, const std::vector<T>& values) {
    const size_t at = bytes.size();
    bytes.resize(at + values.size() * sizeof(T));
    std::memcpy(&bytes[at], values.data(), values.size() * sizeof(T));
}

struct Layout {
    bool interleaved = false;  // positions and normals in one view, byteStride 24
    bool shortIndices = false;
    std::vector<Vec3> normals = {};  // packed layout only; empty: kNormal for every vertex
};

// A glTF of kPositions (normals +Z) and one primitive per entry of `primitives` (each a list
// of corners, all over the same vertex accessors, each with a material of its own), written
// beside its .bin; the imported scene.
Scene importPrimitives(const std::string& name, const std::vector<std::vector<uint32_t>>& primitives,
                       Layout layout) {
    std::string bin;
    std::string views, accessors, prims, materials;
    const size_t n = kPositions.size();
    if (layout.interleaved) {
        std::vector<float> both;
        for (const Vec3& p : kPositions)
            both.insert(both.end(), {p.x, p.y, p.z, kNormal.x, kNormal.y, kNormal.z});
        appendBytes(bin, both);
        views = R"({"buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(24 * n) +
                R"(, "byteStride": 24})";
        accessors = R"({"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 6, "type": "VEC3",
                        "min": [0, 0, 0], "max": [3, 1, 0]},
                       {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 6, "type": "VEC3"})";
    } else {
        appendBytes(bin, kPositions);
        appendBytes(bin, layout.normals.empty() ? std::vector<Vec3>(n, kNormal) : layout.normals);
        views =
            R"({"buffer": 0, "byteOffset": 0, "byteLength": 72}, {"buffer": 0, "byteOffset": 72, "byteLength": 72})";
        accessors = R"({"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3",
                        "min": [0, 0, 0], "max": [3, 1, 0]},
                       {"bufferView": 1, "componentType": 5126, "count": 6, "type": "VEC3"})";
    }
    const int firstView = layout.interleaved ? 1 : 2;
    for (size_t p = 0; p < primitives.size(); ++p) {
        while (bin.size() % 4 != 0) bin.push_back('\0');
        const size_t offset = bin.size();
        if (layout.shortIndices) {
            appendBytes(bin, std::vector<uint16_t>(primitives[p].begin(), primitives[p].end()));
        } else {
            appendBytes(bin, primitives[p]);
        }
        const std::string view = std::to_string(firstView + int(p)), index = std::to_string(2 + p);
        views += R"(, {"buffer": 0, "byteOffset": )" + std::to_string(offset) + R"(, "byteLength": )" +
                 std::to_string(bin.size() - offset) + "}";
        accessors += R"(, {"bufferView": )" + view + R"(, "componentType": )" +
                     (layout.shortIndices ? "5123" : "5125") + R"(, "count": )" +
                     std::to_string(primitives[p].size()) + R"(, "type": "SCALAR"})";
        prims += std::string(p ? ", " : "") + R"({"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": )" +
                 index + R"(, "material": )" + std::to_string(p) + "}";
        materials += std::string(p ? ", " : "") + R"({"name": "m)" + std::to_string(p) + R"("})";
    }
    test::writeTempFile(name + ".bin", bin);
    const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}], "meshes": [{"primitives": [)" +
                             prims + R"(]}],
        "materials": [)" + materials +
                             R"(],
        "buffers": [{"byteLength": )" +
                             std::to_string(bin.size()) + R"(, "uri": ")" + name + R"(.bin"}],
        "bufferViews": [)" + views +
                             R"(], "accessors": [)" + accessors + "]}";
    Scene scene;
    importGltf(test::writeTempFile(name + ".gltf", gltf), 0, scene);
    return scene;
}

TEST(GltfVertexArrays, PrimitivesSharingAnAccessorKeepOnlyTheirVertices) {
    const Scene scene = importPrimitives("shared", {{0, 1, 2}, {5, 4, 3}}, {});
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.positions, (std::vector<Vec3>{kPositions[0], kPositions[1], kPositions[2], kPositions[5],
                                                 kPositions[4], kPositions[3]}));
    EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(mesh.normals, std::vector<Vec3>(6, kNormal));
    EXPECT_EQ(mesh.slotCount, 2u);
    EXPECT_EQ(mesh.primitiveSlots, (std::vector<uint32_t>{0, 1}));
}

TEST(GltfVertexArrays, APrimitiveUsingEveryVertexKeepsTheFilesOrder) {
    for (const Layout& layout : {Layout{false, false}, Layout{true, false}, Layout{false, true}}) {
        const Scene scene = importPrimitives("whole", {{2, 0, 1, 3, 5, 4}}, layout);
        ASSERT_EQ(scene.meshes.size(), 1u);
        const Mesh& mesh = scene.meshes[0];
        const std::string what = std::string(layout.interleaved ? "interleaved" : "packed") +
                                 (layout.shortIndices ? ", 16-bit indices" : ", 32-bit indices");
        EXPECT_EQ(mesh.positions, kPositions) << what;
        EXPECT_EQ(mesh.normals, std::vector<Vec3>(6, kNormal)) << what;
        EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{2, 0, 1, 3, 5, 4})) << what;
        EXPECT_EQ(mesh.slotCount, 1u) << what;
        EXPECT_TRUE(mesh.primitiveSlots.empty()) << what << ": one slot needs no list";
    }
}

// NORMALs are normalised, and zero-length ones replaced by their triangles' normal with one
// warning that counts them (the normalisation runs in parallel, and so does the count).
TEST(GltfVertexArrays, NormalsAreNormalisedAndZeroOnesReplacedWithACountedWarning) {
    Layout layout;
    layout.normals = {{0, 0, 3}, {0, 0, 0}, {0, 0.6f, 0.8f}, {0, 0, 0}, {0, 0, 0.5f}, {0, 0, 1}};
    const Scene scene = importPrimitives("zero_normals", {{0, 1, 2, 3, 4, 5}}, layout);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const std::vector<Vec3> expected = {kNormal, kNormal, {0, 0.6f, 0.8f}, kNormal, kNormal, kNormal};
    for (size_t v = 0; v < expected.size(); ++v) {
        EXPECT_NEAR(scene.meshes[0].normals[v].y, expected[v].y, 1e-6f) << v;
        EXPECT_NEAR(scene.meshes[0].normals[v].z, expected[v].z, 1e-6f) << v;
    }
    size_t warnings = 0;
    for (const std::string& w : scene.warnings) {
        warnings += w.find("2 zero-length NORMAL vectors replaced") != std::string::npos;
    }
    EXPECT_EQ(warnings, 1u);
}

}  // namespace
}  // namespace pt
