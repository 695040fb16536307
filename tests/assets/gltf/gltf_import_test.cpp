// importGltf on the small fixtures of tests/data/gltf (written by make_fixtures.py, which
// says what each one holds): geometry, node hierarchy, materials, textures, camera,
// warnings. Malformed files are in gltf_malformed_test.cpp, the shared sample assets in
// gltf_shared_assets_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "assets/gltf_quad_json.h"
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
    Imported result;
    result.file = importGltf(test::testDataPath("gltf/" + name), 7, result.scene, progress);
    return result;
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

// `name` is a plain pointer: see materialNamed in obj_import_test.cpp.
const Placement& placementNamed(const Imported& imported, const char* name) {
    for (const Placement& p : imported.file.placements) {
        if (p.name == name) return p;
    }
    throw std::runtime_error(std::string("no placement ") + name);
}

Vec3 triangleNormal(const Mesh& mesh, size_t t) {
    const Vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]],
               c = mesh.positions[mesh.indices[3 * t + 2]];
    return normalize(cross(b - a, c - a));
}

TEST(GltfImport, ReadsEveryMaterialFactorAndExtension) {
    const Imported r = importFixture("materials.gltf");
    EXPECT_TRUE(r.scene.warnings.empty()) << r.scene.warnings.front();
    ASSERT_EQ(r.file.placements.size(), 1u);
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    const Mesh& mesh = r.scene.meshes[0];
    EXPECT_EQ(mesh.slotCount, 3u);
    EXPECT_EQ(mesh.primitiveSlots, (std::vector<uint32_t>{0, 0, 1, 1, 2, 2}));
    const Placement& p = r.file.placements[0];
    ASSERT_EQ(p.materials.size(), 3u);
    ASSERT_EQ(r.scene.materials.size(), 3u);
    const NamedMaterial& all = r.scene.materials[p.materials[0]];
    EXPECT_EQ(all.name, "Everything");
    EXPECT_EQ(all.object, 7);
    const Material& m = all.params;
    expectNear(m.baseColor, {0.5f, 0.25f, 0.125f});
    EXPECT_FLOAT_EQ(m.alpha, 0.75f);
    EXPECT_FLOAT_EQ(m.metallic, 0.3f);
    EXPECT_FLOAT_EQ(m.roughness, 0.6f);
    expectNear(m.emission, {1.0f, 0.5f, 0.0f});
    EXPECT_FLOAT_EQ(m.emissionStrength, 5.0f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(m.transmission, 0.8f);
    EXPECT_FLOAT_EQ(m.thickness, 0.2f);
    expectNear(m.attenuationColor, {0.9f, 0.8f, 0.7f});
    EXPECT_FLOAT_EQ(m.attenuationDistance, 3.0f);
    EXPECT_FLOAT_EQ(m.clearcoat, 0.4f);
    EXPECT_FLOAT_EQ(m.clearcoatRoughness, 0.1f);
    EXPECT_FLOAT_EQ(m.specular, 0.9f);
    expectNear(m.specularColor, {0.8f, 0.7f, 0.6f});
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_EQ(m.doubleSided, 1u);
    EXPECT_FLOAT_EQ(m.normalScale, 0.7f);
    EXPECT_FLOAT_EQ(m.baseColorTexture.offset.x, 0.1f);
    EXPECT_FLOAT_EQ(m.baseColorTexture.offset.y, 0.2f);
    EXPECT_FLOAT_EQ(m.baseColorTexture.scale.x, 2.0f);
    EXPECT_FLOAT_EQ(m.baseColorTexture.scale.y, 3.0f);
    EXPECT_FLOAT_EQ(m.baseColorTexture.rotation, 0.5f);
    for (const TextureRef* slot : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture,
                                   &m.emissiveTexture, &m.transmissionTexture}) {
        EXPECT_TRUE(slot->present());
    }

    // One image with two samplers: two Scene textures; emission shares baseColor's.
    ASSERT_EQ(r.scene.textures.size(), 3u);
    const Texture& clamped = r.scene.textures[size_t(m.baseColorTexture.texture)];
    EXPECT_EQ(clamped.wrapS, WrapMode::ClampToEdge);
    EXPECT_EQ(clamped.wrapT, WrapMode::MirroredRepeat);
    EXPECT_TRUE(clamped.nearest);
    EXPECT_EQ(clamped.object, 7);
    EXPECT_EQ(m.emissiveTexture.texture, m.baseColorTexture.texture);
    const Texture& repeated = r.scene.textures[size_t(m.metallicRoughnessTexture.texture)];
    EXPECT_NE(m.metallicRoughnessTexture.texture, m.baseColorTexture.texture);
    EXPECT_EQ(repeated.wrapS, WrapMode::Repeat);
    EXPECT_FALSE(repeated.nearest);
    EXPECT_EQ(repeated.texels8, clamped.texels8);
    EXPECT_EQ(m.normalTexture.texture, m.transmissionTexture.texture);  // the data-URI image
    EXPECT_EQ(r.scene.textures[size_t(m.normalTexture.texture)].width, 2u);
}

TEST(GltfImport, EmptyAndMissingMaterialsTakeGltfDefaults) {
    const Imported r = importFixture("materials.gltf");
    const Placement& p = r.file.placements[0];
    for (uint32_t slot : {1u, 2u}) {
        const Material& m = r.scene.materials[p.materials[slot]].params;
        expectNear(m.baseColor, Vec3(1.0f));
        EXPECT_FLOAT_EQ(m.alpha, 1.0f);
        EXPECT_FLOAT_EQ(m.metallic, 1.0f);
        EXPECT_FLOAT_EQ(m.roughness, 1.0f);
        expectNear(m.emission, Vec3(0.0f));
        EXPECT_EQ(m.doubleSided, 0u);
        EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
        EXPECT_FALSE(m.baseColorTexture.present());
    }
    EXPECT_EQ(r.scene.materials[p.materials[1]].name, "Defaults");
    EXPECT_EQ(r.scene.materials[p.materials[2]].name, "glTF default");
}

TEST(GltfImport, MinimalGlbWithImageInBufferView) {
    const Imported r = importFixture("minimal.glb");
    ASSERT_EQ(r.file.placements.size(), 1u);
    EXPECT_EQ(r.scene.meshes[0].primitiveCount(), 2u);
    ASSERT_EQ(r.scene.textures.size(), 1u);
    const Texture& t = r.scene.textures[0];
    EXPECT_EQ(t.width, 2u);
    EXPECT_EQ(t.height, 2u);
    ASSERT_EQ(t.format, TexelFormat::RGBA8);
    // Texel (0, 1) is blue with alpha 0: straight alpha keeps its color.
    EXPECT_EQ(std::vector<uint8_t>(t.texels8.begin() + 8, t.texels8.begin() + 12),
              (std::vector<uint8_t>{0, 0, 255, 0}));
    EXPECT_EQ(r.scene.materials[r.file.placements[0].materials[0]].params.baseColorTexture.texture, 0);
}

TEST(GltfImport, MeshSharedByTwoNodesIsImportedOnce) {
    const Imported r = importFixture("shared_mesh.gltf");
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    ASSERT_EQ(r.file.placements.size(), 2u);
    EXPECT_EQ(r.file.placements[0].mesh, r.file.placements[1].mesh);
    expectNear(placementNamed(r, "Left").fileToNode.translation(), {-2, 0, 0});
    expectNear(placementNamed(r, "Right").fileToNode.translation(), {2, 0, 0});
    EXPECT_EQ(r.scene.materials.size(), 1u);  // the default material, once
}

TEST(GltfImport, NegativeScaleStaysInTheTransform) {
    const Imported r = importFixture("transforms.gltf");
    const Placement& mirrored = placementNamed(r, "Mirrored");
    EXPECT_LT(mirrored.fileToNode.determinant(), 0.0f);
    // The renderer flips winding from the determinant; indices stay as in the file.
    EXPECT_EQ(r.scene.meshes[mirrored.mesh].indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(GltfImport, MatrixNodeComposesWithItsTrsChild) {
    const Imported r = importFixture("transforms.gltf");
    // Matrix: rotate 90 degrees about Z, then move by (1, 2, 3).
    expectNear(placementNamed(r, "Matrix").fileToNode.transformPoint({1, 0, 0}), {1, 3, 3});
    // Child: scale 2, move +x by 1, then the parent's matrix.
    expectNear(placementNamed(r, "Child").fileToNode.transformPoint({1, 0, 0}), {1, 5, 3});
    EXPECT_FLOAT_EQ(placementNamed(r, "Child").fileToNode.determinant(), 8.0f);
}

TEST(GltfImport, ReadsEveryIndexComponentType) {
    const Imported r = importFixture("index_types.gltf");
    ASSERT_EQ(r.scene.meshes.size(), 3u);
    for (const Mesh& mesh : r.scene.meshes) {
        EXPECT_EQ(mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3})) << mesh.name;
        EXPECT_EQ(mesh.positions.size(), 4u);
    }
}

TEST(GltfImport, NonIndexedPrimitiveGetsFlatNormals) {
    const Imported r = importFixture("non_indexed.gltf");
    const Mesh& mesh = r.scene.meshes.at(0);
    ASSERT_EQ(mesh.primitiveCount(), 2u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    expectNear(triangleNormal(mesh, 0), {0, 0, 1});
    expectNear(triangleNormal(mesh, 1), {-1, 0, 0});
    for (size_t t = 0; t < 2; ++t) {
        for (size_t k = 0; k < 3; ++k) {
            expectNear(mesh.normals[mesh.indices[3 * t + k]], triangleNormal(mesh, t));
        }
    }
}

TEST(GltfImport, StripsAndFansBecomeConsistentlyWoundTriangles) {
    const Imported r = importFixture("topologies.gltf");
    ASSERT_EQ(r.scene.meshes.size(), 3u);
    const Mesh& strip = r.scene.meshes[0];
    const Mesh& fan = r.scene.meshes[1];
    ASSERT_EQ(strip.primitiveCount(), 3u);
    ASSERT_EQ(fan.primitiveCount(), 3u);
    for (size_t t = 0; t < 3; ++t) {
        expectNear(triangleNormal(strip, t), {0, 0, -1});  // the strip starts clockwise
        expectNear(triangleNormal(fan, t), {0, 0, 1});
    }
    // Spec order: the strip's second triangle is {v1, v3, v2}, the fan's first {v1, v2, v0}.
    expectNear(strip.positions[strip.indices[3]], {0, 1, 0});
    expectNear(strip.positions[strip.indices[4]], {1, 1, 0});
    expectNear(fan.positions[fan.indices[2]], {0, 0, 0});
}

TEST(GltfImport, PointsAndLinesAreSkippedWithAWarningEach) {
    const Imported r = importFixture("topologies.gltf");
    const Mesh& mixed = r.scene.meshes[2];
    EXPECT_EQ(mixed.primitiveCount(), 2u);
    EXPECT_EQ(mixed.slotCount, 1u);
    EXPECT_EQ(warningsContaining(r.scene, "topologies.gltf: meshes[2].primitives[0]: POINTS"), 1u);
    EXPECT_EQ(warningsContaining(r.scene, "topologies.gltf: meshes[2].primitives[1]: LINES"), 1u);
    EXPECT_EQ(r.scene.warnings.size(), 2u);
}

TEST(GltfImport, FirstPerspectiveCameraNodeBecomesTheCamera) {
    const Imported r = importFixture("camera.gltf");
    ASSERT_TRUE(r.file.camera.has_value());
    const Camera& c = *r.file.camera;
    expectNear(c.position, {0, 1, 5});
    expectNear(c.lookAt, {-1, 1, 5});  // -Z turned 90 degrees about +Y
    expectNear(c.up, {0, 1, 0});
    EXPECT_NEAR(c.verticalFovDegrees, 0.8f * 180.0f / kPi, 1e-4f);
    EXPECT_EQ(warningsContaining(r.scene, "cameras[0]: 'orthographic' cameras are not supported"), 1u);
    EXPECT_EQ(r.file.placements.size(), 1u);
}

TEST(GltfImport, TexcoordsAsFloatsAndNormalizedIntegers) {
    const Imported r = importFixture("uv_formats.gltf");
    ASSERT_EQ(r.scene.meshes.size(), 3u);
    const std::vector<Vec2> expected = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (const Mesh& mesh : r.scene.meshes) {
        ASSERT_EQ(mesh.uvs.size(), 4u);
        for (size_t i = 0; i < 4; ++i) {
            EXPECT_FLOAT_EQ(mesh.uvs[i].x, expected[i].x);
            EXPECT_FLOAT_EQ(mesh.uvs[i].y, expected[i].y);
        }
    }
}

TEST(GltfImport, SparseAccessorSubstitutesValues) {
    const Imported r = importFixture("sparse.gltf");
    const Mesh& mesh = r.scene.meshes.at(0);
    expectNear(mesh.positions[2], {5, 5, 5});
    expectNear(mesh.positions[1], {1, 0, 0});
}

TEST(GltfImport, MissingImageWarnsOnceAndMaterialsFallBack) {
    const Imported r = importFixture("missing_image.gltf");
    ASSERT_EQ(r.scene.warnings.size(), 1u);
    EXPECT_EQ(r.scene.warnings[0].rfind("missing_image.gltf: images[0] 'does_not_exist.png'", 0), 0u)
        << r.scene.warnings[0];
    EXPECT_TRUE(r.scene.textures.empty());
    const Placement& p = r.file.placements.at(0);
    EXPECT_FALSE(r.scene.materials[p.materials[0]].params.baseColorTexture.present());
    EXPECT_FALSE(r.scene.materials[p.materials[1]].params.emissiveTexture.present());
    expectNear(r.scene.materials[p.materials[1]].params.emission, Vec3(1.0f));
}

TEST(GltfImport, UnsupportedExtensionsWarnAndStillLoad) {
    const Imported r = importFixture("unsupported_extensions.gltf");
    EXPECT_EQ(r.file.placements.size(), 1u);
    // KHR_lights_punctual is supported (gltf_lights_test.cpp): declaring it is not a warning.
    EXPECT_EQ(warningsContaining(r.scene, "KHR_lights_punctual"), 0u);
    EXPECT_EQ(warningsContaining(r.scene, "required extension EXT_lights_image_based"), 1u);
    EXPECT_EQ(warningsContaining(r.scene, "EXT_lights_image_based"), 1u);  // once, not per list
    EXPECT_EQ(warningsContaining(r.scene, "KHR_texture_transform"), 0u);
}

// An optional primitive extension never drops geometry (issue 17: KHR_materials_variants
// primitives were skipped, and a chair lost its fabric and wood): the primitive keeps its
// default material. Only a required one the importer cannot read skips its primitive.
TEST(GltfImport, OptionalPrimitiveExtensionsKeepTheGeometryAndRequiredOnesSkipIt) {
    const Imported r = importFixture("primitive_extensions.gltf");
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    const Mesh& mesh = r.scene.meshes[0];
    EXPECT_EQ(mesh.primitiveCount(), 2u);  // the variants quad's two triangles, not the Draco one's
    ASSERT_EQ(r.file.placements.size(), 1u);
    const std::vector<uint32_t>& materials = r.file.placements[0].materials;
    ASSERT_FALSE(materials.empty());
    EXPECT_EQ(r.scene.materials[materials[0]].name, "default");
    ASSERT_EQ(r.file.placements[0].variantMaterials.size(), 1u);  // read, not shown until chosen
    EXPECT_EQ(r.scene.materials[r.file.placements[0].variantMaterials[0][0]].name, "variant red");
    EXPECT_EQ(warningsContaining(r.scene, "KHR_materials_variants is not supported"), 0u);
    EXPECT_EQ(
        warningsContaining(r.scene, "KHR_materials_variants, which is not supported; primitive skipped"), 0u);
#if defined(PT_TEST_DRACO_FIXTURE)  // decoded where libdraco is: its bytes are no Draco data
    EXPECT_EQ(warningsContaining(r.scene,
                                 "meshes[0].primitives[1].extensions.KHR_draco_mesh_compression: Draco data "
                                 "cannot be decoded: Not a Draco file.; primitive skipped"),
              1u);
#else
    EXPECT_EQ(warningsContaining(r.scene,
                                 "meshes[0].primitives[1]: requires extension KHR_draco_mesh_compression, "
                                 "which is not supported; primitive skipped"),
              1u);
#endif
}

// KHR_materials_variants (variants.gltf, see make_fixtures.py): per placement and variant, the
// material of each slot, a slot the variant does not map keeping its default; malformed
// mappings are ignored with one warning each, never failing the file or dropping geometry.
TEST(GltfImport, MaterialVariantsGiveEachSlotItsMaterialPerVariant) {
    const Imported r = importFixture("variants.gltf");
    EXPECT_EQ(r.file.variants, (std::vector<std::string>{"Leather", "Linen", "variant 2"}));
    ASSERT_EQ(r.file.placements.size(), 3u);
    const auto names = [&](const std::vector<uint32_t>& materials) {
        std::vector<std::string> out;
        for (uint32_t m : materials) out.push_back(r.scene.materials.at(m).name);
        return out;
    };
    using Names = std::vector<std::string>;
    for (size_t chair : {0u, 1u}) {
        const Placement& p = r.file.placements[chair];
        EXPECT_EQ(names(p.materials), (Names{"seat", "frame"}));
        ASSERT_EQ(p.variantMaterials.size(), 3u);
        EXPECT_EQ(names(p.variantMaterials[0]), (Names{"leather", "frame"}));
        EXPECT_EQ(names(p.variantMaterials[1]), (Names{"linen", "gilt"}));
        EXPECT_EQ(names(p.variantMaterials[2]), (Names{"seat", "glow"}));
    }
    EXPECT_EQ(r.file.placements[0].variantMaterials,
              r.file.placements[1].variantMaterials);            // one mesh, shared
    EXPECT_TRUE(r.file.placements[2].variantMaterials.empty());  // the cushion maps nothing
    const std::string mappings = "meshes[0].primitives[0].extensions.KHR_materials_variants.mappings";
    EXPECT_EQ(
        warningsContaining(r.scene, mappings + "[1].variants[1]: is not a variant of the file (3 in it)"),
        1u);
    EXPECT_EQ(warningsContaining(r.scene, mappings + "[2]: material 9 does not exist (6 in the file)"), 1u);
    EXPECT_EQ(
        warningsContaining(r.scene, mappings + "[3]: needs an integer material and an array of variants"),
        1u);
    EXPECT_EQ(r.scene.warnings.size(), 3u) << "no other warning (the extension is supported)";
}

TEST(GltfImport, WithoutScenesEveryRootNodeIsShown) {
    const Imported r = importFixture("no_scenes.gltf");
    EXPECT_EQ(r.file.placements.size(), 3u);
    EXPECT_EQ(r.scene.meshes.size(), 1u);
}

TEST(GltfImport, DataUriBufferLoads) {
    // Every fixture but materials.gltf embeds its buffer as a data URI.
    const Imported r = importFixture("shared_mesh.gltf");
    EXPECT_EQ(r.scene.meshes.at(0).primitiveCount(), 2u);
    expectNear(r.scene.meshes[0].normals[0], {0, 0, 1});
}

TEST(GltfImport, ReportsProgressFromZeroToOne) {
    std::vector<double> fractions;
    importFixture("index_types.gltf", [&](const std::string& stage, double f) {
        EXPECT_EQ(stage, "load glTF");
        fractions.push_back(f);
    });
    ASSERT_GE(fractions.size(), 3u);
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_EQ(fractions.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
}

TEST(GltfImport, FailedImportLeavesTheSceneAsItWas) {
    Scene scene;
    importGltf(test::testDataPath("gltf/materials.gltf"), 0, scene);
    const size_t meshes = scene.meshes.size(), materials = scene.materials.size(),
                 textures = scene.textures.size();
    EXPECT_THROW(importGltf(test::testDataPath("gltf/nan_position.gltf"), 1, scene), InputError);
    EXPECT_EQ(scene.meshes.size(), meshes);
    EXPECT_EQ(scene.materials.size(), materials);
    EXPECT_EQ(scene.textures.size(), textures);
}

TEST(GltfObjDispatch, PicksTheImporterByExtensionIgnoringCase) {
    const std::string upper = test::tempDir() + "/MINIMAL.GLB";
    std::filesystem::copy_file(test::testDataPath("gltf/minimal.glb"), upper,
                               std::filesystem::copy_options::overwrite_existing);
    Scene scene;
    EXPECT_EQ(importModelFile(upper, 0, scene).placements.size(), 1u);
    EXPECT_EQ(importModelFile(test::testDataPath("obj/materials.obj"), 0, scene).placements.size(), 1u);
    try {
        importModelFile(test::tempDir() + "/model.fbx", 0, scene);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("model.fbx: unsupported model format '.fbx'"), std::string::npos)
            << e.what();
    }
}

// KHR_materials_unlit, _diffuse_transmission and _sheen: read, honoured (no warning), with
// the extensions' textures.
TEST(GltfImport, UnlitAndDiffuseTransmissionMaterials) {
    const std::string path = test::writeTempFile("unlit.gltf", R"({"asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_materials_unlit", "KHR_materials_diffuse_transmission", "KHR_materials_sheen"],
  "materials": [{"name": "baked", "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.6, 0.9, 1]},
                 "extensions": {"KHR_materials_unlit": {}}},
                {"name": "lit", "extensions": {"KHR_materials_diffuse_transmission": {
                    "diffuseTransmissionFactor": 0.25, "diffuseTransmissionColorFactor": [0.5, 1, 0.2],
                    "diffuseTransmissionColorTexture": {"index": 0}},
                  "KHR_materials_sheen": {"sheenColorFactor": [0.9, 0.8, 0.7], "sheenRoughnessFactor": 0.3,
                    "sheenColorTexture": {"index": 0}, "sheenRoughnessTexture": {"index": 0}}}}],
  "textures": [{"source": 0}],
  "images": [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg=="}],
  )" + test::quadGltfGeometry() + R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 3, "material": 0},
                             {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 3, "material": 1}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})");
    Scene scene;
    importGltf(path, 0, scene);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].params.unlit, 1u);
    EXPECT_EQ(scene.materials[0].params.baseColor, Vec3(0.3f, 0.6f, 0.9f));
    EXPECT_EQ(scene.materials[1].params.unlit, 0u);
    EXPECT_EQ(scene.materials[1].params.diffuseTransmission, 0.25f);
    EXPECT_EQ(scene.materials[1].params.diffuseTransmissionColor, Vec3(0.5f, 1.0f, 0.2f));
    EXPECT_EQ(scene.materials[0].params.diffuseTransmission, 0.0f);
    EXPECT_TRUE(scene.materials[1].params.diffuseTransmissionColorTexture.present());
    EXPECT_FALSE(scene.materials[1].params.diffuseTransmissionTexture.present());
    EXPECT_EQ(scene.materials[1].params.sheenColor, Vec3(0.9f, 0.8f, 0.7f));
    EXPECT_EQ(scene.materials[1].params.sheenRoughness, 0.3f);
    EXPECT_TRUE(scene.materials[1].params.sheenColorTexture.present());
    EXPECT_TRUE(scene.materials[1].params.sheenRoughnessTexture.present());
    EXPECT_TRUE(scene.gltfExtensions.at("KHR_materials_sheen"));
    EXPECT_TRUE(scene.gltfExtensions.at("KHR_materials_unlit"));
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
}

// A file whose quad has one primitive per material of `materials` (`count` JSON objects), with
// `extensions` declared used and one texture, a 1x1 PNG.
std::string materialsGltf(const std::string& name, const std::string& extensions,
                          const std::string& materials, size_t count) {
    std::string primitives;
    for (size_t i = 0; i < count; ++i) {
        if (i > 0) primitives += ", ";
        primitives += R"({"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, )";
        primitives += R"("material": )" + std::to_string(i) + "}";
    }
    std::string json = R"({"asset": {"version": "2.0"}, "extensionsUsed": [)" + extensions + "],\n";
    json += R"("materials": [)" + materials + "],\n";
    json += R"("textures": [{"source": 0}], "images": [{"uri": "data:image/png;base64,)";
    json +=
        R"(iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg=="}],)";
    json += test::quadGltfGeometry() + R"(, "meshes": [{"primitives": [)" + primitives + "]}],\n";
    json += R"("nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    return test::writeTempFile(name, json);
}

// KHR_materials_anisotropy, _iridescence and _dispersion: every factor and texture read, and
// the extensions' defaults where an object leaves them out; honoured, so no warning.
TEST(GltfImport, AnisotropyIridescenceAndDispersionMaterials) {
    const std::string path = materialsGltf(
        "anisotropy_iridescence_dispersion.gltf",
        R"("KHR_materials_anisotropy", "KHR_materials_iridescence", "KHR_materials_dispersion")",
        R"({"name": "all", "extensions": {
             "KHR_materials_anisotropy": {"anisotropyStrength": 0.6, "anisotropyRotation": 2.5,
                                          "anisotropyTexture": {"index": 0}},
             "KHR_materials_iridescence": {"iridescenceFactor": 0.7, "iridescenceTexture": {"index": 0},
               "iridescenceIor": 1.45, "iridescenceThicknessMinimum": 150, "iridescenceThicknessMaximum": 900,
               "iridescenceThicknessTexture": {"index": 0}},
             "KHR_materials_dispersion": {"dispersion": 0.4}}},
           {"name": "empty objects", "extensions": {"KHR_materials_anisotropy": {},
             "KHR_materials_iridescence": {}, "KHR_materials_dispersion": {}}},
           {"name": "none"})",
        3);
    Scene scene;
    importGltf(path, 0, scene);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    for (const char* name :
         {"KHR_materials_anisotropy", "KHR_materials_iridescence", "KHR_materials_dispersion"})
        EXPECT_TRUE(scene.gltfExtensions.at(name)) << name;
    ASSERT_EQ(scene.materials.size(), 3u);
    const Material& all = scene.materials[0].params;
    EXPECT_EQ(all.anisotropyStrength, 0.6f);
    EXPECT_EQ(all.anisotropyRotation, 2.5f) << "radians, as in the file";
    EXPECT_TRUE(all.anisotropyTexture.present());
    EXPECT_EQ(all.iridescence, 0.7f);
    EXPECT_EQ(all.iridescenceIor, 1.45f);
    EXPECT_EQ(all.iridescenceThicknessMin, 150.0f);
    EXPECT_EQ(all.iridescenceThicknessMax, 900.0f);
    EXPECT_TRUE(all.iridescenceTexture.present());
    EXPECT_TRUE(all.iridescenceThicknessTexture.present());
    EXPECT_EQ(all.dispersion, 0.4f);
    for (size_t i : {1u, 2u}) {
        SCOPED_TRACE(scene.materials[i].name);
        const Material& m = scene.materials[i].params;
        EXPECT_EQ(m.anisotropyStrength, 0.0f);
        EXPECT_EQ(m.anisotropyRotation, 0.0f);
        EXPECT_FALSE(m.anisotropyTexture.present());
        EXPECT_EQ(m.iridescence, 0.0f);
        EXPECT_EQ(m.iridescenceIor, 1.3f);
        EXPECT_EQ(m.iridescenceThicknessMin, 100.0f);
        EXPECT_EQ(m.iridescenceThicknessMax, 400.0f);
        EXPECT_FALSE(m.iridescenceTexture.present());
        EXPECT_FALSE(m.iridescenceThicknessTexture.present());
        EXPECT_EQ(m.dispersion, 0.0f);
    }
}

// The KHR_materials_volume_scatter proposal: both drafts' names for the colour, the anisotropy
// clamped to [-1, 1] with a warning, and one warning for the texture that is not read.
TEST(GltfImport, VolumeScatterProposal) {
    const std::string path =
        materialsGltf("volume_scatter.gltf", R"("KHR_materials_volume", "KHR_materials_volume_scatter")",
                      R"({"name": "old", "extensions": {"KHR_materials_volume": {"thicknessFactor": 1},
             "KHR_materials_volume_scatter": {"multiscatterColor": [0.2, 0.4, 0.6], "scatterAnisotropy": 0.5}}},
           {"name": "new", "extensions": {"KHR_materials_volume_scatter": {
             "multiscatterColorFactor": [0.9, 0.8, 0.7], "multiscatterColorTexture": {"index": 0},
             "scatterAnisotropy": -3}}},
           {"name": "empty", "extensions": {"KHR_materials_volume_scatter": {}}})",
                      3);
    Scene scene;
    importGltf(path, 0, scene);
    EXPECT_TRUE(scene.gltfExtensions.at("KHR_materials_volume_scatter"));
    ASSERT_EQ(scene.materials.size(), 3u);
    EXPECT_EQ(scene.materials[0].params.scatterColor, Vec3(0.2f, 0.4f, 0.6f));
    EXPECT_EQ(scene.materials[0].params.scatterAnisotropy, 0.5f);
    EXPECT_EQ(scene.materials[1].params.scatterColor, Vec3(0.9f, 0.8f, 0.7f));
    EXPECT_EQ(scene.materials[1].params.scatterAnisotropy, -1.0f);
    EXPECT_EQ(scene.materials[2].params.scatterColor, Vec3(0.0f));
    EXPECT_EQ(scene.materials[2].params.scatterAnisotropy, 0.0f);
    ASSERT_EQ(scene.warnings.size(), 2u) << ::testing::PrintToString(scene.warnings);
    EXPECT_NE(
        scene.warnings[0].find("materials[1].extensions.KHR_materials_volume_scatter.scatterAnisotropy"),
        std::string::npos)
        << scene.warnings[0];
    EXPECT_NE(scene.warnings[1].find("multiscatterColorTexture is not supported"), std::string::npos)
        << scene.warnings[1];
}

// Values outside what the extensions allow are clamped with one warning each, naming the value;
// one no float holds is an error, as for every number.
TEST(GltfImport, AnisotropyIridescenceAndDispersionOutOfRangeWarnOnceEach) {
    const std::string extensions =
        R"("KHR_materials_anisotropy", "KHR_materials_iridescence", "KHR_materials_dispersion")";
    const std::string path = materialsGltf("out_of_range_extensions.gltf", extensions,
                                           R"({"extensions": {
             "KHR_materials_anisotropy": {"anisotropyStrength": 1.5, "anisotropyRotation": -7},
             "KHR_materials_iridescence": {"iridescenceFactor": -0.25, "iridescenceIor": 0.5,
               "iridescenceThicknessMinimum": -10, "iridescenceThicknessMaximum": 300},
             "KHR_materials_dispersion": {"dispersion": -1}}})",
                                           1);
    Scene scene;
    importGltf(path, 0, scene);
    const Material& m = scene.materials.at(0).params;
    EXPECT_EQ(m.anisotropyStrength, 1.0f);
    EXPECT_EQ(m.anisotropyRotation, -7.0f) << "any angle";
    EXPECT_EQ(m.iridescence, 0.0f);
    EXPECT_EQ(m.iridescenceIor, 1.0f);
    EXPECT_EQ(m.iridescenceThicknessMin, 0.0f);
    EXPECT_EQ(m.iridescenceThicknessMax, 300.0f);
    EXPECT_EQ(m.dispersion, 0.0f);
    EXPECT_EQ(scene.warnings.size(), 5u);
    const std::string base = "out_of_range_extensions.gltf: materials[0].extensions.";
    for (const char* warning :
         {"KHR_materials_anisotropy.anisotropyStrength: 1.5 is above 1; 1 used",
          "KHR_materials_iridescence.iridescenceFactor: -0.25 is below 0; 0 used",
          "KHR_materials_iridescence.iridescenceIor: 0.5 is below 1; 1 used",
          "KHR_materials_iridescence.iridescenceThicknessMinimum: -10 is below 0; 0 used",
          "KHR_materials_dispersion.dispersion: -1 is below 0; 0 used"}) {
        EXPECT_EQ(warningsContaining(scene, base + warning), 1u) << warning;
    }

    const std::string huge =
        materialsGltf("huge_dispersion.gltf", extensions,
                      R"({"extensions": {"KHR_materials_dispersion": {"dispersion": 1e39}}})", 1);
    Scene other;
    try {
        importGltf(huge, 0, other);
        ADD_FAILURE() << "a dispersion beyond float range imported";
    } catch (const InputError& e) {
        EXPECT_NE(
            std::string(e.what()).find(
                "materials[0].extensions.KHR_materials_dispersion.dispersion: expected a finite number"),
            std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace pt
