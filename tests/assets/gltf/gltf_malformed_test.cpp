// Malformed glTF: each file must give an InputError that starts with the file's name and
// names the bad element, and must never crash or read out of bounds (run these under the
// PT_SANITIZE build too). Fixtures: tests/data/gltf (make_fixtures.py says what each one
// breaks) and ../shared/assets/BoundsChecking (tinygltf's own malformed samples).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "assets/input_error.h"
#include "assets/model_import.h"
#include "support/test_paths.h"

namespace pt {
namespace {

std::string importError(const std::string& path) {
    Scene scene;
    try {
        importGltf(path, 0, scene);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << path << " imported without an error";
    return "";
}

struct Case {
    const char* file;
    std::vector<const char*> mustContain;
};

void expectError(const std::string& path, const Case& c) {
    const std::string message = importError(path);
    EXPECT_EQ(message.rfind(std::filesystem::path(path).filename().string() + ": ", 0), 0u)
        << "message does not start with the file name: " << message;
    for (const char* text : c.mustContain) {
        EXPECT_NE(message.find(text), std::string::npos)
            << c.file << ": expected '" << text << "' in: " << message;
    }
}

TEST(GltfMalformed, EachFixtureNamesTheBadElement) {
    const std::vector<Case> cases = {
        {"accessor_past_view.gltf",
         {"meshes[0].primitives[0]: POSITION accessor 0 reads past the end of bufferView 0"}},
        {"view_past_buffer.gltf", {"bufferViews[1]: bytes [", "past the end of buffer 0"}},
        {"index_past_vertex_count.gltf",
         {"meshes[0].primitives[0]: indices accessor 1 element 5 is 7, past the vertex count 4"}},
        {"nan_position.gltf", {"meshes[0].primitives[0]: POSITION accessor 0 element 2 is not finite"}},
        {"inf_position.gltf", {"meshes[0].primitives[0]: POSITION accessor 0 element 2 is not finite"}},
        {"bytelength_1e300.gltf", {"buffers[0].byteLength: expected a whole number", "1e+300"}},
        {"missing_bin.gltf", {"buffers[0].uri: buffer file 'missing.bin' not found"}},
        {"node_cycle.gltf", {"nodes[0]: reached twice in the node hierarchy"}},
        {"bad_material_index.gltf",
         {"meshes[0].primitives[0].material: material 5 does not exist (0 in the file)"}},
        {"bad_mesh_index.gltf", {"nodes[0].mesh: mesh 3 does not exist (1 in the file)"}},
        {"bad_node_index.gltf", {"scenes[0].nodes[1]: node 9 does not exist"}},
        {"bad_accessor_index.gltf",
         {"meshes[0].primitives[0].attributes.NORMAL: accessor 40 does not exist"}},
        {"bad_texture_index.gltf",
         {"materials[0].pbrMetallicRoughness.baseColorTexture.index: texture 9 does not exist"}},
        {"bad_json.gltf", {"invalid JSON"}},
        {"truncated.glb", {"GLB chunk 1: length runs past the file"}},
        {"image_view_past_buffer.glb", {"bufferViews[0]: bytes [4096,", "past the end of buffer 0"}},
    };
    for (const Case& c : cases) expectError(test::testDataPath(std::string("gltf/") + c.file), c);
}

TEST(GltfMalformed, SharedBoundsCheckingFilesNameTheBadElement) {
    PT_REQUIRE_SHARED_ASSET("BoundsChecking/integer-out-of-bounds.gltf");
    const std::vector<Case> cases = {
        {"integer-out-of-bounds.gltf", {"bufferViews[0].byteLength: expected a whole number", "1e+300"}},
        {"invalid-buffer-index.gltf", {"bufferViews[1].buffer: buffer 1 does not exist (1 in the file)"}},
        {"invalid-buffer-view-index.gltf",
         {"accessors[0].bufferView: bufferView 1 does not exist (1 in the file)"}},
        {"invalid-primitive-indices.gltf",
         {"meshes[0].primitives[0].indices: accessor 1 does not exist (1 in the file)"}},
    };
    for (const Case& c : cases) {
        expectError(test::sharedAsset(std::string("BoundsChecking/") + c.file), c);
    }
}

std::vector<char> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every prefix, and every single-byte corruption, of a valid .glb either imports or throws
// InputError; under PT_SANITIZE this also proves no out-of-bounds read on the way.
TEST(GltfMalformed, TruncatedAndCorruptedGlbNeverCrash) {
    const std::vector<char> glb = readBytes(test::testDataPath("gltf/minimal.glb"));
    ASSERT_GT(glb.size(), 100u);
    size_t attempts = 0;
    auto attempt = [&](const std::vector<char>& bytes) {
        // A fresh name each time: truncating one file over and over is slow on some
        // filesystems (overlayfs), creating new ones is not.
        const std::string name = "corrupt" + std::to_string(attempts++) + ".glb";
        const std::string path = test::tempDir() + "/" + name;
        std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
        Scene scene;
        try {
            importGltf(path, 0, scene);
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(name + ": ", 0), 0u) << e.what();
        }
        std::filesystem::remove(path);
    };
    for (size_t length = 0; length < glb.size(); length += 3) {
        attempt(std::vector<char>(glb.begin(), glb.begin() + std::ptrdiff_t(length)));
    }
    for (size_t at = 0; at < glb.size(); ++at) {
        for (char value : {char(0xff), char(0x00), char(0x7f)}) {
            std::vector<char> bytes = glb;
            bytes[at] = value;
            attempt(bytes);
        }
    }
}

}  // namespace
}  // namespace pt
