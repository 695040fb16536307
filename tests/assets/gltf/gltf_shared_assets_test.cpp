// Every model in ../shared/assets imported with its expected counts, plus the facts each
// asset is there to exercise. Skips where the shared assets are absent.
//
// Expected counts were computed independently of the importer by
// tests/data/gltf/count_gltf_facts.py, which reads only the glTF JSON: it walks the default
// scene and sums, over the nodes that have a mesh, the triangles of each primitive
// (index or POSITION count / 3); materials are those the reached primitives use (plus the
// default one), textures the distinct (image, sampler) pairs of the imported slots minus
// .ktx2 images. For the OBJ: `awk '/^f /{t += NF - 3} END {print t}' cornell_box.obj` and
// the four `newmtl` entries of cornell_box.mtl.
#include <gtest/gtest.h>

#include <algorithm>

#include "assets/model_import.h"
#include "support/test_paths.h"

namespace pt {
namespace {

struct Expected {
    const char* path;
    uint64_t triangles;
    size_t placements, materials, textures;
};

// Names the case in test output (gtest would print the struct's bytes).
void PrintTo(const Expected& e, std::ostream* os) { *os << e.path; }

struct Imported {
    Scene scene;
    ImportedFile file;
    uint64_t triangles = 0;  // summed over placements
};

Imported importShared(const std::string& path) {
    Imported r;
    r.file = importModelFile(test::sharedAsset(path), 0, r.scene);
    for (const Placement& p : r.file.placements) r.triangles += r.scene.meshes.at(p.mesh).primitiveCount();
    return r;
}

size_t warningsContaining(const Scene& scene, const std::string& text) {
    return size_t(std::count_if(scene.warnings.begin(), scene.warnings.end(),
                                [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

class GltfSharedAsset : public testing::TestWithParam<Expected> {};

TEST_P(GltfSharedAsset, ImportsWithTheExpectedCounts) {
    const Expected& e = GetParam();
    PT_REQUIRE_SHARED_ASSET(e.path);
    const Imported r = importShared(e.path);
    EXPECT_EQ(r.triangles, e.triangles);
    EXPECT_EQ(r.file.placements.size(), e.placements);
    EXPECT_EQ(r.scene.materials.size(), e.materials);
    EXPECT_EQ(r.scene.textures.size(), e.textures);
    for (const Placement& p : r.file.placements) {
        const Mesh& mesh = r.scene.meshes.at(p.mesh);
        ASSERT_EQ(p.materials.size(), mesh.slotCount);
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
        for (uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size());
        for (const Vec3& n : mesh.normals) ASSERT_NEAR(length(n), 1.0f, 1e-3f);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Shared, GltfSharedAsset,
    testing::Values(Expected{"CornellBox/CornellBox.glb", 36, 4, 5, 0},
                    Expected{"GolfBall/GolfBall.glb", 356, 1, 1, 1},
                    Expected{"DepthOfFieldExample/DepthOfFieldExample.glb", 10610, 16, 3, 5},
                    Expected{"TonemappingTest/TonemappingTest.gltf", 6590, 3, 8, 1},
                    Expected{"Fox/Fox.glb", 576, 1, 1, 1}, Expected{"SimpleSkin/SimpleSkin.gltf", 8, 1, 1, 0},
                    Expected{"AnisotropyBarnLamp/AnisotropyBarnLamp.gltf", 10203, 3, 3, 1},
                    Expected{"Balloon/scene.gltf", 35698, 37, 37, 18},
                    Expected{"CornellBoxObj/cornell_box.obj", 3968, 1, 4, 0}),
    [](const testing::TestParamInfo<Expected>& param) {
        std::string name = param.param.path;
        name = name.substr(0, name.find('/'));
        return name;
    });

TEST(GltfSharedAssets, SimpleSkinGetsTheDefaultMaterialAndGeneratedNormals) {
    PT_REQUIRE_SHARED_ASSET("SimpleSkin/SimpleSkin.gltf");
    const Imported r = importShared("SimpleSkin/SimpleSkin.gltf");
    ASSERT_EQ(r.scene.materials.size(), 1u);
    EXPECT_EQ(r.scene.materials[0].name, "glTF default");
    EXPECT_FLOAT_EQ(r.scene.materials[0].params.metallic, 1.0f);
    const Mesh& mesh = r.scene.meshes.at(0);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_EQ(mesh.positions.size(), 3 * size_t(mesh.primitiveCount()));         // flat: unshared
    for (const Vec3& n : mesh.normals) EXPECT_NEAR(std::abs(n.z), 1.0f, 1e-5f);  // a flat XY strip
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_EQ(r.scene.warnings.size(), 0u) << "skins and animations are applied (gltf_animation_test.cpp)";
}

TEST(GltfSharedAssets, AnisotropyBarnLampWarnsOncePerUndecodableImageAndLoads) {
    PT_REQUIRE_SHARED_ASSET("AnisotropyBarnLamp/AnisotropyBarnLamp.gltf");
    const Imported r = importShared("AnisotropyBarnLamp/AnisotropyBarnLamp.gltf");
    // The normal, metallic-roughness and anisotropy slots use three .ktx2 images (the first
    // also through clearcoatNormalTexture, the second through occlusionTexture): one warning
    // each. KHR_materials_anisotropy itself is honoured: its strength is read, its texture
    // slot falls back to none like the others.
    EXPECT_EQ(warningsContaining(r.scene, "AnisotropyBarnLamp_normalbump.ktx2"), 1u);
    EXPECT_EQ(warningsContaining(r.scene, "AnisotropyBarnLamp_occlusionroughnessmetal.ktx2"), 1u);
    EXPECT_EQ(warningsContaining(r.scene, "AnisotropyBarnLamp_anisotropy.ktx2"), 1u);
    EXPECT_EQ(warningsContaining(r.scene, ".ktx2"), 3u);
    EXPECT_EQ(warningsContaining(r.scene, "KHR_materials_anisotropy"), 0u);
    EXPECT_TRUE(r.scene.gltfExtensions.at("KHR_materials_anisotropy"));
    const Material& metal = r.scene.materials[r.file.placements.at(0).materials.at(0)].params;
    EXPECT_TRUE(metal.baseColorTexture.present());
    EXPECT_FALSE(metal.normalTexture.present());
    EXPECT_FALSE(metal.metallicRoughnessTexture.present());
    EXPECT_FALSE(metal.anisotropyTexture.present());
    EXPECT_FLOAT_EQ(metal.anisotropyStrength, 1.0f);
    EXPECT_FLOAT_EQ(metal.anisotropyRotation, 0.0f);
    EXPECT_TRUE(std::any_of(r.scene.materials.begin(), r.scene.materials.end(),
                            [](const NamedMaterial& m) { return m.params.anisotropyStrength > 0.0f; }));
    EXPECT_FLOAT_EQ(metal.clearcoat, 0.25f);
    const Material& glass = r.scene.materials[r.file.placements.at(2).materials.at(0)].params;
    EXPECT_FLOAT_EQ(glass.transmission, 1.0f);
    EXPECT_FLOAT_EQ(glass.thickness, 0.01f);
}

TEST(GltfSharedAssets, CornellBoxEmitterHasStrength100) {
    PT_REQUIRE_SHARED_ASSET("CornellBox/CornellBox.glb");
    const Imported r = importShared("CornellBox/CornellBox.glb");
    const auto emitters = std::count_if(
        r.scene.materials.begin(), r.scene.materials.end(),
        [](const NamedMaterial& m) { return m.params.isEmissive() && m.params.emissionStrength == 100.0f; });
    EXPECT_EQ(emitters, 1);
    for (const NamedMaterial& m : r.scene.materials) EXPECT_EQ(m.params.doubleSided, 1u);
}

TEST(GltfSharedAssets, DepthOfFieldExampleHas16MeshesOn17Nodes) {
    PT_REQUIRE_SHARED_ASSET("DepthOfFieldExample/DepthOfFieldExample.glb");
    const Imported r = importShared("DepthOfFieldExample/DepthOfFieldExample.glb");
    EXPECT_EQ(r.scene.meshes.size(), 16u);
    EXPECT_EQ(r.file.placements.size(), 16u);  // the 17th node is the sun, a light
    EXPECT_EQ(warningsContaining(r.scene, "KHR_lights_punctual"), 0u);
    ASSERT_EQ(r.file.lights.size(), 1u) << "the 17th node is the sun, a light";
    EXPECT_EQ(r.file.lights[0].type, LightType::Directional);
    EXPECT_EQ(r.file.lights[0].intensity, 6830.0f) << "lux";
    const auto lava = std::find_if(r.scene.materials.begin(), r.scene.materials.end(),
                                   [](const NamedMaterial& m) { return m.params.emissionStrength == 20.0f; });
    EXPECT_NE(lava, r.scene.materials.end());
}

TEST(GltfSharedAssets, BalloonHasAbout35698Triangles) {
    PT_REQUIRE_SHARED_ASSET("Balloon/scene.gltf");
    const Imported r = importShared("Balloon/scene.gltf");
    EXPECT_EQ(r.triangles, 35698u);
    EXPECT_TRUE(r.scene.warnings.empty()) << r.scene.warnings.front();
    for (const Texture& t : r.scene.textures) {
        EXPECT_EQ(t.format, TexelFormat::RGBA8);
        EXPECT_EQ(t.texels8.size(), size_t(t.width) * t.height * 4);
    }
}

}  // namespace
}  // namespace pt
