// Scene JSON: reading every key, writing only non-defaults, exact float round trips, and one
// error message per kind of bad input (file name + JSON path + what).
#include "assets/scene_json/scene_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "assets/input_error.h"
#include "assets/scene_loader.h"
#include "assets/scene_test_helpers.h"
#include "support/load_scene.h"

namespace pt {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::scenesEqual;
using test::testDataPath;
using test::testFolder;
using test::writeFile;

// Saves `scene` to `path`, loads it back and checks that nothing changed.
Scene saveAndReload(const Scene& scene, const std::string& path) {
    writeSceneJson(scene, path);
    Scene again = test::loadSceneOrFail(path);
    EXPECT_TRUE(scenesEqual(scene, again)) << "saved as:\n" << readFile(path);
    return again;
}

TEST(SceneJson, EveryKeyIsRead) {
    const Scene scene = test::loadSceneOrFail(testDataPath("json/every_key.json"));
    EXPECT_EQ(scene.camera.position, Vec3(1.5f, 2.25f, 7.0f));
    EXPECT_EQ(scene.camera.up, Vec3(0.0f, 1.0f, 0.1f));
    EXPECT_EQ(scene.camera.verticalFovDegrees, 33.3f);
    EXPECT_EQ(scene.camera.apertureRadius, 0.05f);
    EXPECT_EQ(scene.camera.focusDistance, 6.5f);
    EXPECT_TRUE(scene.cameraFromFile);
    EXPECT_EQ(scene.render.width, 320u);
    EXPECT_EQ(scene.render.height, 200u);
    EXPECT_EQ(scene.render.maxDepth, 12u);
    EXPECT_EQ(scene.render.spp, 7u);
    EXPECT_EQ(scene.render.seed, 42u);
    EXPECT_EQ(scene.environment.color, Vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(scene.environment.imagePath,
              fs::path(testDataPath("json/images/sky.hdr")).lexically_normal().string());
    ASSERT_GE(scene.environment.texture, 0);
    EXPECT_EQ(scene.textures[size_t(scene.environment.texture)].width, 2u);
    EXPECT_EQ(scene.environment.intensity, 2.5f);
    EXPECT_EQ(scene.environment.rotationDegrees, 90.0f);
    EXPECT_EQ(scene.textures.size(), 2u) << "each image is loaded once however many slots name it";

    const Material& plastic = scene.materials[size_t(findSceneMaterial(scene, "plastic"))].params;
    EXPECT_EQ(plastic.baseColor, Vec3(0.9f, 0.1f, 0.2f));
    EXPECT_EQ(plastic.specularColor, Vec3(0.9f, 0.8f, 1.2f));
    EXPECT_EQ(plastic.attenuationDistance, 2.0f);
    EXPECT_EQ(plastic.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(plastic.doubleSided, 0u);
    EXPECT_EQ(plastic.normalScale, 0.8f);
    EXPECT_TRUE(plastic.baseColorTexture.present());
    EXPECT_EQ(plastic.metallicRoughnessTexture.offset.x, 0.5f);
    EXPECT_EQ(plastic.metallicRoughnessTexture.scale.y, 3.0f);
    EXPECT_NEAR(plastic.metallicRoughnessTexture.rotation, kPi / 6.0f, 1e-6f)
        << "degrees in JSON, radians inside";
    EXPECT_EQ(plastic.transmissionTexture.texture, plastic.baseColorTexture.texture);
    EXPECT_EQ(plastic.unlit, 0u);
    EXPECT_EQ(plastic.diffuseTransmission, 0.4f);
    EXPECT_EQ(plastic.diffuseTransmissionColor, Vec3(0.3f, 0.9f, 0.5f));
    EXPECT_EQ(plastic.sheenColor, Vec3(0.8f, 0.7f, 0.6f));
    EXPECT_EQ(plastic.sheenRoughness, 0.45f);
    EXPECT_EQ(plastic.anisotropyStrength, 0.65f);
    EXPECT_NEAR(plastic.anisotropyRotation, -kPi / 3.0f, 1e-6f) << "degrees in JSON, radians inside";
    EXPECT_EQ(plastic.iridescence, 0.9f);
    EXPECT_EQ(plastic.iridescenceIor, 1.8f);
    EXPECT_EQ(plastic.iridescenceThicknessMin, 250.0f);
    EXPECT_EQ(plastic.iridescenceThicknessMax, 750.0f);
    EXPECT_EQ(plastic.dispersion, 2.5f);
    for (const TextureRef* slot :
         {&plastic.diffuseTransmissionTexture, &plastic.diffuseTransmissionColorTexture,
          &plastic.sheenColorTexture, &plastic.sheenRoughnessTexture, &plastic.anisotropyTexture,
          &plastic.iridescenceTexture, &plastic.iridescenceThicknessTexture})
        EXPECT_EQ(slot->texture, plastic.baseColorTexture.texture);
    EXPECT_EQ(scene.materials[size_t(findSceneMaterial(scene, "poster"))].params.unlit, 1u);

    ASSERT_EQ(scene.objects.size(), 5u);
    EXPECT_EQ(scene.objects[0].materialOverrides.at("paint"), "chrome");
    EXPECT_TRUE(scene.objects[1].transform.useMatrix);
    EXPECT_EQ(scene.objects[2].kind, ObjectKind::Sphere);
    EXPECT_EQ(scene.objects[2].transform.scale, Vec3(0.5f));
    EXPECT_EQ(scene.objects[4].material, kDefaultMaterialName);
    const int32_t chrome = findSceneMaterial(scene, "chrome");
    for (const Instance& instance : scene.instances) {
        if (instance.object == 0) {
            EXPECT_EQ(instance.materials, std::vector<uint32_t>{uint32_t(chrome)});
        }
    }
}

TEST(SceneJson, LightsAreRead) {
    const Scene scene = test::loadSceneOrFail(testDataPath("json/every_key.json"));
    ASSERT_EQ(scene.lights.size(), 3u);
    const Light& bulb = scene.lights[0];
    EXPECT_EQ(bulb.name, "bulb");
    EXPECT_EQ(bulb.type, LightType::Point);
    EXPECT_EQ(bulb.color, Vec3(1.0f, 0.8f, 0.6f));
    EXPECT_EQ(bulb.intensity, 25.0f);
    EXPECT_EQ(bulb.position, Vec3(1, 3, 2));
    EXPECT_EQ(bulb.object, -1);
    const Light& key = scene.lights[1];
    EXPECT_EQ(key.type, LightType::Spot);
    EXPECT_EQ(key.direction, Vec3(0.0f, -1.0f, 0.2f)) << "kept as written; normalised when compiled";
    EXPECT_EQ(key.innerConeDegrees, 15.0f);
    EXPECT_EQ(key.outerConeDegrees, 35.0f);
    const Light& sun = scene.lights[2];
    EXPECT_EQ(sun.name, "");
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_EQ(sun.intensity, 3.5f);
    EXPECT_EQ(sun.direction, Vec3(-1, -2, -1));

    // Written with only what differs from the defaults and applies to the type.
    const std::string folder = testFolder();
    const std::string text = sceneToJson(scene, folder + "/out.json");
    EXPECT_NE(text.find(R"({
      "type": "directional",
      "color": [1.0, 0.95, 0.9],
      "intensity": 3.5,
      "direction": [-1.0, -2.0, -1.0]
    })"),
              std::string::npos)
        << text;
    saveAndReload(scene, folder + "/out.json");
}

// Lights that come from a model file are placed with its object, are not written to the
// JSON (the file brings them back), and make the loader leave the environment alone.
TEST(SceneJson, ModelFileLightsMoveWithTheirObjectAndAreNotWritten) {
    const std::string folder = testFolder();
    const std::string model = testDataPath("gltf/lights.gltf");
    const Scene scene =
        test::loadSceneOrFail(writeFile(folder, "scene.json", R"({"version": 1, "lights": [{"type": "point"}],
        "objects": [{"file": ")" + model + R"(", "transform": {"translate": [10, 0, 0]}}]})"));
    ASSERT_EQ(scene.lights.size(), 4u);
    EXPECT_EQ(scene.lights[0].object, -1);
    EXPECT_EQ(scene.lights[1].name, "bulb");
    EXPECT_EQ(scene.lights[1].object, 0);
    EXPECT_EQ(scene.lights[1].position, Vec3(11, 2, 3));
    const std::string text = sceneToJson(scene, folder + "/out.json");
    EXPECT_EQ(text.find("bulb"), std::string::npos) << text;
    saveAndReload(scene, folder + "/out.json");
}

TEST(SceneJson, PresetsSetDefaultsAndKeysOverrideThem) {
    const std::string folder = testFolder();
    const Scene scene =
        test::loadSceneOrFail(writeFile(folder, "presets.json", R"({"version": 1, "materials": [
        {"name": "d", "type": "diffuse"}, {"name": "m", "type": "mirror"}, {"name": "g", "type": "glass"},
        {"name": "tinted", "type": "mirror", "baseColor": [0.9, 0.5, 0.2], "roughness": 0.1},
        {"name": "frosted", "type": "glass", "roughness": 0.25, "ior": 1.33}]})"));
    auto params = [&](const char* name) {
        return scene.materials[size_t(findSceneMaterial(scene, name))].params;
    };
    EXPECT_EQ(params("d").metallic, 0.0f);
    EXPECT_EQ(params("d").specular, 0.0f);
    EXPECT_EQ(params("m").metallic, 1.0f);
    EXPECT_EQ(params("m").roughness, 0.0f);
    EXPECT_EQ(params("m").baseColor, Vec3(1.0f));
    EXPECT_EQ(params("g").transmission, 1.0f);
    EXPECT_EQ(params("g").roughness, 0.0f);
    EXPECT_EQ(params("g").ior, 1.5f);
    EXPECT_EQ(params("tinted").baseColor, Vec3(0.9f, 0.5f, 0.2f));
    EXPECT_EQ(params("tinted").roughness, 0.1f);
    EXPECT_EQ(params("tinted").metallic, 1.0f);
    EXPECT_EQ(params("frosted").roughness, 0.25f);
    EXPECT_EQ(params("frosted").ior, 1.33f);

    // Written expanded, never as a preset, in schema order, defaults left out.
    const std::string text = sceneToJson(scene, folder + "/out.json");
    EXPECT_EQ(text.find("\"type\""), std::string::npos) << text;
    EXPECT_NE(text.find(R"({
      "name": "m",
      "baseColor": [1.0, 1.0, 1.0],
      "metallic": 1.0,
      "roughness": 0.0
    },)"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(R"({
      "name": "frosted",
      "roughness": 0.25,
      "ior": 1.33,
      "transmission": 1.0
    })"),
              std::string::npos)
        << text;
    saveAndReload(scene, folder + "/out.json");
}

TEST(SceneJson, MinimalSceneSavesMinimalFile) {
    const std::string folder = testFolder();
    const Scene scene = test::loadSceneOrFail(
        writeFile(folder, "in.json", R"({"version": 1, "objects": [{"shape": "sphere"}]})"));
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].name, kDefaultMaterialName);
    EXPECT_FALSE(scene.cameraFromFile);
    // The default material, the framing camera and every default setting are left out.
    EXPECT_EQ(sceneToJson(scene, folder + "/out.json"),
              "{\n"
              "  \"version\": 1,\n"
              "  \"objects\": [\n"
              "    {\n"
              "      \"shape\": \"sphere\"\n"
              "    }\n"
              "  ]\n"
              "}\n");
    saveAndReload(scene, folder + "/out.json");
    // A scene built in code keeps Camera{}, which the loader would not compute: written, empty.
    EXPECT_EQ(sceneToJson(Scene{}, folder + "/empty.json"), "{\n  \"version\": 1,\n  \"camera\": {}\n}\n");
}

TEST(SceneJson, EveryKeyRoundTripsAndOutputIsStable) {
    const std::string folder = testFolder();
    fs::create_directories(folder + "/elsewhere");
    const Scene first = test::loadSceneOrFail(testDataPath("json/every_key.json"));
    const Scene second = saveAndReload(first, folder + "/elsewhere/every_key.json");
    const std::string text = readFile(folder + "/elsewhere/every_key.json");
    EXPECT_EQ(sceneToJson(second, folder + "/elsewhere/every_key.json"), text) << "same scene, same text";
    // Floats print as their shortest exact decimal, not as the double nearest the float.
    EXPECT_NE(text.find("\"baseColor\": [0.9, 0.1, 0.2]"), std::string::npos) << text;
    EXPECT_NE(text.find("\"rotation\": 30.0"), std::string::npos) << text;
    EXPECT_NE(text.find("\"anisotropyRotation\": -60.0"), std::string::npos) << "degrees, as read";
    EXPECT_NE(text.find("\"fov\": 33.3"), std::string::npos) << text;
    EXPECT_NE(text.find("\"scale\": 0.5"), std::string::npos) << "uniform scale stays one number";
    const std::string sky = fs::path(testDataPath("json/images/sky.hdr"))
                                .lexically_normal()
                                .lexically_relative(fs::path(folder) / "elsewhere")
                                .generic_string();
    EXPECT_NE(text.find("\"image\": \"" + sky + "\""), std::string::npos) << "paths relative to the output";
}

// The media keys (issue 15) are read, written only where they differ from Material{}'s, and
// read back bit for bit; the "subsurface" and "fog" types start from what their names say.
TEST(SceneJson, MediaKeysRoundTrip) {
    const std::string folder = testFolder();
    const Scene scene = test::loadSceneOrFail(writeFile(folder, "in.json", R"({"version": 1, "materials": [
        {"name": "skin", "type": "subsurface", "subsurfaceColor": [0.9, 0.6, 0.5], "subsurfaceRadius": 0.002,
         "subsurfaceRadiusScale": [1, 0.4, 0.2], "scatterAnisotropy": -0.3},
        {"name": "haze", "type": "fog", "scatterColor": [0.7, 0.8, 0.9]},
        {"name": "plain"}],
      "objects": [{"shape": "sphere", "material": "skin"}, {"shape": "box", "material": "haze"},
                  {"shape": "quad", "material": "plain"}]})"));
    const Material& skin = scene.materials[size_t(findSceneMaterial(scene, "skin"))].params;
    EXPECT_EQ(skin.subsurface, 1.0f);
    EXPECT_EQ(skin.subsurfaceColor, Vec3(0.9f, 0.6f, 0.5f));
    EXPECT_EQ(skin.subsurfaceRadius, 0.002f);
    EXPECT_EQ(skin.subsurfaceRadiusScale, Vec3(1.0f, 0.4f, 0.2f));
    EXPECT_EQ(skin.scatterAnisotropy, -0.3f);
    const Material& haze = scene.materials[size_t(findSceneMaterial(scene, "haze"))].params;
    EXPECT_EQ(haze.scatterColor, Vec3(0.7f, 0.8f, 0.9f));
    EXPECT_EQ(haze.ior, 1.0f);
    EXPECT_GT(haze.thickness, 0.0f);
    const std::string text = sceneToJson(scene, folder + "/out.json");
    EXPECT_NE(text.find(R"("subsurfaceRadius": 0.002)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("name": "plain"
    })"),
              std::string::npos)
        << "no media keys where none was set: " << text;
    const Scene again = saveAndReload(scene, folder + "/out.json");
    EXPECT_TRUE(scenesEqual(again, scene));
}

// The keys of KHR_materials_anisotropy, _iridescence and _dispersion are written only where a
// value differs from Material{}'s (the extensions' own defaults), and read back bit for bit.
TEST(SceneJson, AnisotropyIridescenceAndDispersionKeysAreWrittenOnlyWhenSet) {
    const std::string folder = testFolder();
    const Scene scene = test::loadSceneOrFail(writeFile(folder, "in.json", R"({"version": 1, "materials": [
        {"name": "lid", "anisotropyStrength": 0.8, "anisotropyRotation": 12.5},
        {"name": "bubble", "iridescence": 1, "iridescenceThicknessMax": 600},
        {"name": "flint", "type": "glass", "dispersion": 1},
        {"name": "plain", "iridescenceIor": 1.3, "iridescenceThicknessMin": 100, "anisotropyRotation": 0}],
      "objects": [{"shape": "sphere", "material": "lid"}, {"shape": "box", "material": "bubble"},
                  {"shape": "quad", "material": "flint"}, {"shape": "sphere", "material": "plain"}]})"));
    const std::string text = sceneToJson(scene, folder + "/out.json");
    EXPECT_NE(text.find(R"("name": "lid",
      "anisotropyStrength": 0.8,
      "anisotropyRotation": 12.5
    })"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(R"("name": "bubble",
      "iridescence": 1.0,
      "iridescenceThicknessMax": 600.0
    })"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(R"("dispersion": 1.0)"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("name": "plain"
    })"),
              std::string::npos)
        << "the defaults, written out in the input, are left out: " << text;
    const Scene again = saveAndReload(scene, folder + "/out.json");
    EXPECT_EQ(again.materials[size_t(findSceneMaterial(again, "lid"))].params.anisotropyRotation,
              scene.materials[size_t(findSceneMaterial(scene, "lid"))].params.anisotropyRotation);
}

// Random values of every float kind (denormals, huge, negative zero, many digits) survive
// load -> save -> load bit for bit.
TEST(SceneJson, FloatsRoundTripExactly) {
    std::mt19937 rng(1234);
    auto bitsFloat = [&] {  // any finite float, by its bits
        for (;;) {
            const uint32_t bits = rng();
            float f;
            std::memcpy(&f, &bits, sizeof f);
            if (std::isfinite(f) && std::fabs(f) < 1e30f) return f;
        }
    };
    auto unit = [&] { return std::uniform_real_distribution<float>(0.0f, 1.0f)(rng); };
    auto text = [](float f) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.9g", double(f));
        return std::string(buffer);
    };
    auto triple = [&](auto make) {
        return "[" + text(make()) + ", " + text(make()) + ", " + text(make()) + "]";
    };
    std::string json = R"({"version": 1, "camera": {"position": )" + triple(bitsFloat) +
                       R"(, "lookAt": [0, 0, 0], "fov": )" + text(unit() * 170.0f + 1.0f) +
                       R"(}, "environment": {"intensity": )" + text(unit()) + R"(, "rotation": )" +
                       text(bitsFloat()) + R"(}, "materials": [)";
    for (int i = 0; i < 200; ++i) {
        json += std::string(i ? "," : "") + R"({"name": "m)" + std::to_string(i) + R"(", "baseColor": )" +
                triple(unit) + R"(, "roughness": )" + text(unit() * 1e-3f) + R"(, "ior": )" +
                text(1.0f + unit()) + R"(, "normalScale": )" + text(bitsFloat()) + R"(, "emission": )" +
                triple(unit) + "}";
    }
    json += R"(], "objects": [)";
    for (int i = 0; i < 100; ++i) {
        json += std::string(i ? "," : "") + R"({"shape": "box", "material": "m)" + std::to_string(i) +
                R"(", "transform": {"translate": )" + triple(bitsFloat) + R"(, "rotate": )" +
                triple([&] { return unit() * 720.0f - 360.0f; }) + R"(, "scale": )" +
                triple([&] { return 0.01f + unit() * 100.0f; }) + "}}";
    }
    json +=
        R"(, {"shape": "quad", "transform": {"translate": [-0.0, 0, 0], "scale": [-1e-3, 1e-20, 1e20]}}]})";
    const std::string folder = testFolder();
    const Scene scene = test::loadSceneOrFail(writeFile(folder, "random.json", json));
    const Scene again = saveAndReload(scene, folder + "/saved.json");
    EXPECT_EQ(sceneToJson(again, folder + "/saved.json"), readFile(folder + "/saved.json"));
}

// The scenes the project ships are read, and survive a save elsewhere bit for bit.
TEST(SceneJson, ShippedScenesRoundTrip) {
    const std::string folder = testFolder();
    size_t count = 0;
    for (const auto& entry : fs::directory_iterator(test::projectPath("scenes"))) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const Scene scene = test::loadSceneOrFail(entry.path().string());
        saveAndReload(scene, folder + "/" + entry.path().filename().string());
        ++count;
    }
    EXPECT_GT(count, 0u);
}

// One case per kind of bad input: the JSON, and the whole expected message ("{folder}"
// stands for the folder the scene is written to).
struct ErrorCase {
    const char* name;
    const char* fileName;
    const char* json;
    const char* message;
};

const ErrorCase kErrorCases[] = {
    {"UnknownKeyIsNamedWithASuggestion", "cornell.json",
     R"({"version": 1, "materials": [{"name": "a"}, {"name": "b"}, {"name": "c", "rouhgness": 0.2}]})",
     R"(cornell.json: materials[2]: unknown key "rouhgness" (did you mean "roughness"?))"},
    {"UnknownRootKey", "scene.json", R"({"version": 1, "objetcs": []})",
     R"(scene.json: unknown key "objetcs" (did you mean "objects"?))"},
    {"UnknownTransformKey", "scene.json",
     R"({"version": 1, "objects": [{"shape": "box", "transform": {"translation": [1, 2, 3]}}]})",
     R"(scene.json: objects[0].transform: unknown key "translation")"},
    {"ScaleWithWrongCount", "cornell.json",
     R"({"version": 1, "objects": [{"shape": "box"}, {"shape": "box"}, {"shape": "box"},
        {"shape": "box", "transform": {"scale": [1, 2]}}]})",
     "cornell.json: objects[3].transform.scale: expected 3 numbers"},
    {"WrongType", "scene.json", R"({"version": 1, "render": {"spp": "64"}})",
     R"(scene.json: render.spp: expected an integer, got "64")"},
    {"WrongContainerType", "scene.json", R"({"version": 1, "objects": {"shape": "box"}})",
     "scene.json: objects: expected an array, got an object"},
    {"MissingVersion", "scene.json", R"({"objects": []})", R"(scene.json: missing key "version")"},
    {"MissingMaterialName", "scene.json", R"({"version": 1, "materials": [{"type": "diffuse"}]})",
     R"(scene.json: materials[0]: missing key "name")"},
    {"NeitherFileNorShape", "scene.json", R"({"version": 1, "objects": [{"name": "x"}]})",
     R"(scene.json: objects[0]: missing key "file" or "shape")"},
    {"MissingModelFile", "scene.json", R"({"version": 1, "objects": [{"file": "models/gone.obj"}]})",
     "scene.json: objects[0].file: no such file: {folder}/models/gone.obj"},
    {"MissingTextureFile", "scene.json",
     R"({"version": 1, "materials": [{"name": "a", "baseColorTexture": {"image": "gone.png"}}]})",
     "scene.json: materials[0].baseColorTexture.image: no such file: {folder}/gone.png"},
    {"MissingEnvironmentImage", "scene.json", R"({"version": 1, "environment": {"image": "sky.exr"}})",
     "scene.json: environment.image: no such file: {folder}/sky.exr"},
    {"DuplicateMaterialName", "scene.json",
     R"({"version": 1, "materials": [{"name": "red"}, {"name": "red"}]})",
     R"(scene.json: materials[1].name: duplicate material name "red" (also materials[0]))"},
    {"UnknownMaterialName", "scene.json",
     R"({"version": 1, "materials": [{"name": "green"}], "objects": [{"shape": "box", "material": "gren"}]})",
     R"(scene.json: objects[0].material: unknown material "gren")"},
    {"NumberBeyondFloatRange", "scene.json",
     R"({"version": 1, "materials": [{"name": "a", "normalScale": 1e39}]})",
     "scene.json: materials[0].normalScale: expected a finite number (within 32-bit float range), got 1e+39"},
    {"NumberBeyondDoubleRange", "scene.json", R"({"version": 1, "camera": {"fov": 1e400}})",
     "scene.json: number overflow parsing '1e400'"},
    {"ZeroScaleWouldMakeNaN", "scene.json",
     R"({"version": 1, "objects": [{"shape": "sphere", "transform": {"scale": [1, 0, 1]}}]})",
     "scene.json: objects[0].transform.scale: the transform is not invertible (a zero or extreme scale)"},
    {"SingularMatrix", "scene.json",
     R"({"version": 1, "objects": [{"shape": "box", "transform": {"matrix": [0,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}}]})",
     "scene.json: objects[0].transform.matrix: the transform is not invertible (a zero or extreme scale)"},
    {"MatrixNotAffine", "scene.json",
     R"({"version": 1, "objects": [{"shape": "box", "transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,1, 0,0,0,1]}}]})",
     "scene.json: objects[0].transform.matrix: not affine: elements 3, 7, 11, 15 (the last row) must be 0, "
     "0, 0, 1"},
    {"MatrixWithTrs", "scene.json",
     R"({"version": 1, "objects": [{"shape": "box", "transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "scale": 2}}]})",
     R"(scene.json: objects[0].transform: "matrix" excludes "translate", "rotate" and "scale")"},
    {"NegativeSpp", "scene.json", R"({"version": 1, "render": {"spp": -4}})",
     "scene.json: render.spp: expected an integer in [1, 4294967295], got -4"},
    {"ZeroResolution", "scene.json", R"({"version": 1, "render": {"resolution": [640, 0]}})",
     "scene.json: render.resolution[1]: expected an integer in [1, 32768], got 0"},
    {"ResolutionNotAPair", "scene.json", R"({"version": 1, "render": {"resolution": 640}})",
     "scene.json: render.resolution: expected [width, height], got 640"},
    {"ParameterOutOfRange", "scene.json", R"({"version": 1, "materials": [{"name": "a", "roughness": 1.5}]})",
     "scene.json: materials[0].roughness: expected a number in [0, 1], got 1.5"},
    {"NegativeDispersion", "scene.json", R"({"version": 1, "materials": [{"name": "a", "dispersion": -1}]})",
     "scene.json: materials[0].dispersion: expected a number >= 0, got -1"},
    {"IridescenceIorBelowOne", "scene.json",
     R"({"version": 1, "materials": [{"name": "a", "iridescenceIor": 0.5}]})",
     "scene.json: materials[0].iridescenceIor: expected a number >= 1, got 0.5"},
    {"FovOutOfRange", "scene.json", R"({"version": 1, "camera": {"fov": 180}})",
     "scene.json: camera.fov: expected a number in (0, 180), got 180"},
    {"CameraWithoutViewDirection", "scene.json", R"({"version": 1, "camera": {"position": [0, 0, 0]}})",
     "scene.json: camera: lookAt equals position: no view direction"},
    {"CameraUpAlongView", "scene.json", R"({"version": 1, "camera": {"up": [0, 0, -2]}})",
     "scene.json: camera.up: up is zero or parallel to the view direction"},
    {"UnknownPreset", "scene.json", R"({"version": 1, "materials": [{"name": "a", "type": "metal"}]})",
     R"(scene.json: materials[0].type: unknown material type "metal" (expected "diffuse", "mirror", "glass", "subsurface" or "fog"))"},
    {"ScatterAnisotropyPastOne", "scene.json",
     R"({"version": 1, "materials": [{"name": "a", "scatterAnisotropy": 1.5}]})",
     "scene.json: materials[0].scatterAnisotropy: expected a number in [-1, 1], got 1.5"},
    {"UnknownAlphaMode", "scene.json",
     R"({"version": 1, "materials": [{"name": "a", "alphaMode": "cutout"}]})",
     R"(scene.json: materials[0].alphaMode: unknown alpha mode "cutout" (expected "opaque", "mask" or "blend"))"},
    {"UnknownShape", "scene.json", R"({"version": 1, "objects": [{"shape": "cone"}]})",
     R"(scene.json: objects[0].shape: unknown shape "cone" (expected "sphere", "box" or "quad"))"},
    {"FileAndShape", "scene.json", R"({"version": 1, "objects": [{"shape": "box", "file": "a.obj"}]})",
     R"(scene.json: objects[0]: "file" and "shape" exclude each other)"},
    {"OverridesOnShape", "scene.json",
     R"({"version": 1, "objects": [{"shape": "box", "materialOverrides": {"a": "b"}}]})",
     R"(scene.json: objects[0].materialOverrides: applies to file objects; a shape takes "material")"},
    {"UnsupportedModelFormat", "scene.json", R"({"version": 1, "objects": [{"file": "scene.json"}]})",
     R"(scene.json: objects[0].file: unsupported model format ".json" (expected .gltf, .glb or .obj))"},
    {"NewerVersion", "scene.json", R"({"version": 2, "keyFromTheFuture": true})",
     "scene.json: version: 2 is newer than the newest version this program reads (1)"},
    {"DuplicateKey", "scene.json",
     R"({"version": 1, "materials": [{"name": "a", "roughness": 0.1, "roughness": 0.2}]})",
     R"(scene.json: materials[0]: duplicate key "roughness")"},
    {"UnknownLightKey", "scene.json", R"({"version": 1, "lights": [{"type": "point", "intensty": 3}]})",
     R"(scene.json: lights[0]: unknown key "intensty" (did you mean "intensity"?))"},
    {"MissingLightType", "scene.json", R"({"version": 1, "lights": [{"intensity": 3}]})",
     R"(scene.json: lights[0]: missing key "type")"},
    {"UnknownLightType", "scene.json", R"({"version": 1, "lights": [{"type": "area"}]})",
     R"(scene.json: lights[0].type: unknown light type "area" (expected "point", "spot" or "directional"))"},
    {"PositionOfADirectionalLight", "scene.json",
     R"({"version": 1, "lights": [{"type": "directional", "position": [0, 1, 0]}]})",
     "scene.json: lights[0].position: a directional light has no position (it is infinitely far away)"},
    {"DirectionOfAPointLight", "scene.json",
     R"({"version": 1, "lights": [{"type": "point"}, {"type": "point", "direction": [0, -1, 0]}]})",
     "scene.json: lights[1].direction: a point light shines in every direction; it takes no direction"},
    {"ConeOfADirectionalLight", "scene.json",
     R"({"version": 1, "lights": [{"type": "directional", "outerConeAngle": 30}]})",
     "scene.json: lights[0].outerConeAngle: a directional light has no cone"},
    {"InnerConeNotInsideOuter", "scene.json",
     R"({"version": 1, "lights": [{"type": "spot", "innerConeAngle": 40, "outerConeAngle": 30}]})",
     "scene.json: lights[0].innerConeAngle: expected degrees in [0, outerConeAngle), got 40"},
    {"OuterConeBeyondHemisphere", "scene.json",
     R"({"version": 1, "lights": [{"type": "spot", "outerConeAngle": 95}]})",
     "scene.json: lights[0].outerConeAngle: expected degrees in (0, 90], got 95"},
    {"ZeroLightDirection", "scene.json",
     R"({"version": 1, "lights": [{"type": "spot", "direction": [0, 0, 0]}]})",
     "scene.json: lights[0].direction: the direction is zero"},
    {"NegativeLightIntensity", "scene.json",
     R"({"version": 1, "lights": [{"type": "point", "intensity": -1}]})",
     "scene.json: lights[0].intensity: expected a number >= 0, got -1"},
    {"SyntaxErrorNamesLineAndColumn", "scene.json", "{\n  \"version\": 1,\n  \"objects\": [\n}",
     "scene.json: line 4, column 1: syntax error while parsing value - unexpected '}'; expected '[', '{', or "
     "a literal"},
};

void PrintTo(const ErrorCase& c, std::ostream* out) { *out << c.name; }

class SceneJsonError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneJsonError, MessageNamesFileJsonPathAndProblem) {
    const ErrorCase& c = GetParam();
    const std::string folder = testFolder();
    const LoadResult result = loadScene(writeFile(folder, c.fileName, c.json));
    ASSERT_FALSE(result.ok());
    std::string expected = c.message;
    const size_t at = expected.find("{folder}");
    if (at != std::string::npos) expected.replace(at, 8, folder);
    EXPECT_EQ(result.error, expected);
    EXPECT_THROW(readSceneJson(folder + "/" + c.fileName), InputError);
}

INSTANTIATE_TEST_SUITE_P(AllKinds, SceneJsonError, ::testing::ValuesIn(kErrorCases),
                         [](const ::testing::TestParamInfo<ErrorCase>& c) {
                             return std::string(c.param.name);
                         });

TEST(SceneJsonErrors, ImporterErrorKeepsItsMessageUnderTheObjectPath) {
    const std::string folder = testFolder();
    writeFile(folder, "models/broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    const LoadResult result = loadScene(
        writeFile(folder, "scene.json", R"({"version": 1, "objects": [{"file": "models/broken.obj"}]})"));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error.rfind("scene.json: objects[0].file: ", 0), 0u) << result.error;
    EXPECT_NE(result.error.find("broken.obj"), std::string::npos) << "the importer's message names its file";
}

TEST(SceneJsonErrors, UnknownOverrideKeyAndUnknownOverrideTarget) {
    const std::string folder = testFolder();
    const std::string model = testDataPath("json/models/panel.obj");
    LoadResult result =
        loadScene(writeFile(folder, "a.json", R"({"version": 1, "materials": [{"name": "blue"}],
        "objects": [{"file": ")" + model + R"(", "materialOverrides": {"pain": "blue"}}]})"));
    EXPECT_EQ(result.error, R"(a.json: objects[0].materialOverrides.pain: panel.obj has no material "pain")");
    result = loadScene(writeFile(folder, "b.json", R"({"version": 1,
        "objects": [{"file": ")" + model + R"(", "materialOverrides": {"paint": "blue"}}]})"));
    EXPECT_EQ(result.error, R"(b.json: objects[0].materialOverrides.paint: unknown material "blue")");
}

// "variant" names one of a glTF's KHR_materials_variants: every instance of the object shows
// it (overrides applied to the variant's materials too), the other objects keep their
// defaults, and saving writes it back.
TEST(SceneJson, MaterialVariantIsChosenByNameAndSaved) {
    const std::string folder = testFolder();
    const std::string model = testDataPath("gltf/variants.gltf");
    const Scene scene = test::loadSceneOrFail(writeFile(folder, "in.json", R"({"version": 1,
        "materials": [{"name": "brass", "baseColor": [0.9, 0.7, 0.3]}],
        "objects": [{"name": "shown", "file": ")" + model + R"(", "variant": "Linen",
                     "materialOverrides": {"gilt": "brass"}},
                    {"name": "default", "file": ")" + model + R"("}]})"));
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].variant, 1);
    EXPECT_EQ(scene.objects[1].variant, -1);
    EXPECT_EQ(scene.objects[1].variants, (std::vector<std::string>{"Leather", "Linen", "variant 2"}));
    const auto slotNames = [&](const Instance& instance) {
        std::vector<std::string> out;
        for (uint32_t m : instance.materials) out.push_back(scene.materials.at(m).name);
        return out;
    };
    using Names = std::vector<std::string>;
    size_t chairs = 0;
    for (const Instance& instance : scene.instances) {
        if (instance.name == "cushion") {
            EXPECT_EQ(slotNames(instance), (Names{"seat"}));
            continue;
        }
        ++chairs;
        EXPECT_EQ(slotNames(instance),
                  instance.object == 0 ? (Names{"linen", "brass"}) : (Names{"seat", "frame"}))
            << instance.name;
    }
    EXPECT_EQ(chairs, 4u);
    const Scene again = saveAndReload(scene, folder + "/out.json");
    EXPECT_NE(readFile(folder + "/out.json").find("\"variant\": \"Linen\""), std::string::npos);
    EXPECT_EQ(again.objects[0].variant, 1);
}

TEST(SceneJsonErrors, UnknownVariantNamesTheFilesVariants) {
    const std::string folder = testFolder();
    LoadResult result = loadScene(writeFile(folder, "a.json",
                                            R"({"version": 1,
        "objects": [{"file": ")" + testDataPath("gltf/variants.gltf") +
                                                R"(", "variant": "Velvet"}]})"));
    EXPECT_EQ(result.error, R"(a.json: objects[0].variant: "Velvet" is not a variant of variants.gltf )"
                            R"((its variants: "Leather", "Linen", "variant 2"))");
    result = loadScene(writeFile(folder, "b.json",
                                 R"({"version": 1,
        "objects": [{"file": ")" + testDataPath("gltf/shared_mesh.gltf") +
                                     R"(", "variant": "Linen"}]})"));
    EXPECT_EQ(result.error, "b.json: objects[0].variant: shared_mesh.gltf has no material variants");
    result = loadScene(writeFile(folder, "c.json", R"({"version": 1,
        "objects": [{"shape": "box", "variant": "Linen"}]})"));
    EXPECT_EQ(result.error,
              "c.json: objects[0].variant: applies to file objects; shapes have no material variants");
}

TEST(SceneJsonErrors, UnreadableImageKeepsTheReadersMessage) {
    const std::string folder = testFolder();
    writeFile(folder, "fake.png", "not a png");
    const LoadResult result =
        loadScene(writeFile(folder, "scene.json",
                            R"({"version": 1, "materials": [{"name": "a", "normalTexture": "fake.png"}]})"));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error.rfind("scene.json: materials[0].normalTexture: ", 0), 0u) << result.error;
}

TEST(SceneJsonErrors, EmbeddedTextureCannotBeSaved) {
    Scene scene;
    Texture texture;
    texture.name = "model.glb: images[0]";
    scene.textures.push_back(texture);
    NamedMaterial material{"painted", Material{}, -1};
    material.params.baseColorTexture.texture = 0;
    scene.materials.push_back(material);
    try {
        (void)sceneToJson(scene, testFolder() + "/out.json");
        FAIL() << "wrote a texture that has no file";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "out.json: materials[0].baseColorTexture: texture \"model.glb: images[0]\" is "
                     "embedded in a model file; scene JSON can only name image files");
    }
}

}  // namespace
}  // namespace pt
