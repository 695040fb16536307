// importObj on the hand-written fixtures of tests/data/obj (each file's comment says what
// it holds) and the MTL mapping of assets/obj_materials.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "assets/input_error.h"
#include "assets/model_import.h"
#include "support/test_paths.h"

namespace pt {
namespace {

struct Imported {
    Scene scene;
    ImportedFile file;
};

Imported importFixture(const std::string& name, const ProgressFn& progress = {}) {
    Imported r;
    r.file = importObj(test::testDataPath("obj/" + name), 3, r.scene, progress);
    return r;
}

std::string importError(const std::string& name) {
    Scene scene;
    try {
        importObj(test::testDataPath("obj/" + name), 0, scene);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << name << " imported without an error";
    return "";
}

size_t warningsContaining(const Scene& scene, const std::string& text) {
    return size_t(std::count_if(scene.warnings.begin(), scene.warnings.end(),
                                [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

void expectNear(Vec3 actual, Vec3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// `name` is a plain pointer: a std::string temporary would make GCC 13 flag the references
// bound to the result (-Wdangling-reference).
const Material& materialNamed(const Imported& r, const char* name) {
    for (uint32_t index : r.file.placements.at(0).materials) {
        if (r.scene.materials.at(index).name == name) return r.scene.materials[index].params;
    }
    throw std::runtime_error(std::string("no material ") + name);
}

TEST(ObjImport, OneMeshOnePlacementOneSlotPerMtlMaterialPlusDefault) {
    const Imported r = importFixture("materials.obj");
    EXPECT_TRUE(r.scene.warnings.empty()) << r.scene.warnings.front();
    ASSERT_EQ(r.file.placements.size(), 1u);
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    const Placement& p = r.file.placements[0];
    const Mesh& mesh = r.scene.meshes[p.mesh];
    EXPECT_EQ(p.name, "materials");
    EXPECT_FLOAT_EQ(p.fileToNode.determinant(), 1.0f);
    expectNear(p.fileToNode.translation(), Vec3(0.0f));
    EXPECT_EQ(mesh.primitiveCount(), 5u);
    EXPECT_EQ(mesh.positions.size(), 4u);  // corners deduplicated
    EXPECT_EQ(mesh.slotCount, 8u);         // 7 MTL materials + the default
    ASSERT_EQ(p.materials.size(), 8u);
    EXPECT_EQ(r.scene.materials[p.materials[7]].name, "OBJ default");
    EXPECT_EQ(r.scene.materials[p.materials[0]].object, 3);
    // Triangle 0 has no usemtl; then Red (slot 0) twice, Lamp (slot 1) twice.
    EXPECT_EQ(mesh.primitiveSlots, (std::vector<uint32_t>{7, 0, 0, 1, 1}));
    for (const Vec3& n : mesh.normals) expectNear(n, {0, 0, 1});
}

TEST(ObjImport, TexcoordsAreFlippedToGltfConvention) {
    const Imported r = importFixture("materials.obj");
    const Mesh& mesh = r.scene.meshes.at(0);
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        // vt equals the position's xy in this file; v' = 1 - v.
        EXPECT_FLOAT_EQ(mesh.uvs[v].x, mesh.positions[v].x);
        EXPECT_FLOAT_EQ(mesh.uvs[v].y, 1.0f - mesh.positions[v].y);
    }
}

TEST(ObjImport, MapsMtlParameters) {
    const Imported r = importFixture("materials.obj");
    const Material& red = materialNamed(r, "Red");
    expectNear(red.baseColor, {1, 0, 0});
    EXPECT_FLOAT_EQ(red.metallic, 0.0f);
    EXPECT_FLOAT_EQ(red.roughness, 1.0f);  // Ns 0
    const Material& lamp = materialNamed(r, "Lamp");
    expectNear(lamp.emission, {5, 4, 3});
    EXPECT_NEAR(lamp.roughness, std::sqrt(2.0f / 252.0f), 1e-6f);
    ASSERT_TRUE(lamp.baseColorTexture.present());
    EXPECT_FLOAT_EQ(lamp.baseColorTexture.scale.x, 2.0f);
    EXPECT_FLOAT_EQ(lamp.baseColorTexture.offset.y, -1.0f);  // -s 2 in the flipped v
    ASSERT_EQ(r.scene.textures.size(), 1u);
    EXPECT_EQ(r.scene.textures[0].width, 2u);
    const Material& glass = materialNamed(r, "Glass");
    EXPECT_FLOAT_EQ(glass.transmission, 1.0f);
    EXPECT_FLOAT_EQ(glass.ior, 1.5f);
    expectNear(glass.baseColor, {0.9f, 0.95f, 1.0f});
    const Material& mirror = materialNamed(r, "Mirror");
    EXPECT_FLOAT_EQ(mirror.metallic, 1.0f);
    expectNear(mirror.baseColor, {0.9f, 0.8f, 0.7f});
    expectNear(materialNamed(r, "Gray").baseColor, Vec3(0.5f));  // "Kd 0.5" is gray
    EXPECT_FLOAT_EQ(materialNamed(r, "Faded").alpha, 0.25f);
    EXPECT_EQ(materialNamed(r, "Faded").alphaMode, AlphaMode::Blend);
    EXPECT_FLOAT_EQ(materialNamed(r, "Placeholder").ior, 1.5f);  // "Ni 1.0" is not glass
}

TEST(ObjImport, MissingNormalsAreSmoothInSmoothingGroupsAndFlatOtherwise) {
    const Imported r = importFixture("smoothing.obj");
    const Mesh& mesh = r.scene.meshes.at(0);
    ASSERT_EQ(mesh.primitiveCount(), 4u);
    const Vec3 bisector = normalize(Vec3(0, 1, 1));
    // Smooth triangles: v1 and v2 (split by the UV seam) share the bisector.
    for (size_t t = 0; t < 2; ++t) {
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t v = mesh.indices[3 * t + k];
            const Vec3 p = mesh.positions[v];
            if (p.y == 0.0f && p.z == 0.0f) expectNear(mesh.normals[v], bisector);
        }
    }
    expectNear(mesh.normals[mesh.indices[2]], {0, 0, 1});  // v3 only in the first
    expectNear(mesh.normals[mesh.indices[5]], {0, 1, 0});  // v4 only in the second
    // Flat triangles: every corner has its triangle's normal.
    for (size_t k = 6; k < 9; ++k) expectNear(mesh.normals[mesh.indices[k]], {0, 0, 1});
    for (size_t k = 9; k < 12; ++k) expectNear(mesh.normals[mesh.indices[k]], {0, 1, 0});
    EXPECT_EQ(mesh.positions.size(), 6u + 6u);  // smooth: 4 + 2 seam copies; flat: 6
}

TEST(ObjImport, MissingMtlWarnsAndUsesTheDefaultMaterial) {
    const Imported r = importFixture("missing_mtl.obj");
    EXPECT_GE(warningsContaining(r.scene, "nope.mtl"), 1u);
    for (const std::string& w : r.scene.warnings) EXPECT_EQ(w.rfind("missing_mtl.obj: ", 0), 0u) << w;
    ASSERT_EQ(r.file.placements.at(0).materials.size(), 1u);
    EXPECT_EQ(r.scene.materials.at(0).name, "OBJ default");
}

TEST(ObjImport, MissingTextureWarnsOnceAndFallsBack) {
    const Imported r = importFixture("missing_texture.obj");
    EXPECT_EQ(warningsContaining(r.scene, "nope.png"), 1u);
    EXPECT_TRUE(r.scene.textures.empty());
    EXPECT_FALSE(materialNamed(r, "A").baseColorTexture.present());
    EXPECT_FALSE(materialNamed(r, "B").baseColorTexture.present());
}

TEST(ObjImport, LinesAndPointsAreSkippedWithOneWarning) {
    const Imported r = importFixture("lines.obj");
    EXPECT_EQ(r.scene.meshes.at(0).primitiveCount(), 1u);
    EXPECT_EQ(warningsContaining(r.scene, "lines.obj: 2 line and point elements"), 1u);
}

TEST(ObjImport, MalformedInputNamesFileAndLine) {
    const std::vector<std::pair<const char*, const char*>> cases = {
        {"bad_number.obj", "bad_number.obj: line 3: 'abc' is not a finite number"},
        {"huge_number.obj", "huge_number.obj: line 3: '1e999' is not a finite number"},
        {"bad_index.obj", "bad_index.obj: line 4: v index 9 is past the 3 v entries"},
        {"zero_index.obj", "zero_index.obj: line 4: v index 0"},
        {"negative_index.obj", "negative_index.obj: line 4: v index -4 reaches before the first v"},
        {"bad_normal_index.obj", "bad_normal_index.obj: line 5: vn index 2 is past the 1 vn entries"},
        {"bad_mtl.obj", "bad_number.mtl: line 2: 'x' is not a finite number"},
        {"does_not_exist.obj", "does_not_exist.obj: cannot open"},
    };
    for (const auto& [file, expected] : cases) {
        const std::string message = importError(file);
        EXPECT_NE(message.find(expected), std::string::npos) << file << ": " << message;
    }
}

TEST(ObjImport, ReportsProgressFromZeroToOne) {
    std::vector<double> fractions;
    importFixture("materials.obj", [&](const std::string& stage, double f) {
        EXPECT_EQ(stage, "load OBJ");
        fractions.push_back(f);
    });
    ASSERT_GE(fractions.size(), 2u);
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_EQ(fractions.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
}

TEST(ObjImport, SharedCornellBoxObj) {
    PT_REQUIRE_SHARED_ASSET("CornellBoxObj/cornell_box.obj");
    Scene scene;
    const ImportedFile file = importObj(test::sharedAsset("CornellBoxObj/cornell_box.obj"), 0, scene);
    ASSERT_EQ(file.placements.size(), 1u);
    // awk '/^f /{t += NF - 3} END {print t}' cornell_box.obj
    EXPECT_EQ(scene.meshes.at(0).primitiveCount(), 3968u);
    EXPECT_EQ(scene.materials.size(), 4u);  // Green, Material.001, Metal, Red
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.slotCount, 4u);
    for (const Vec3& n : mesh.normals) ASSERT_NEAR(length(n), 1.0f, 1e-4f);
}

}  // namespace
}  // namespace pt
