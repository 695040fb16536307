// KHR_lights_punctual and TANGENT import: lights placed by the node hierarchy, their glTF
// values and units kept, malformed references rejected; tangents normalised.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "assets/input_error.h"
#include "assets/model_import.h"
#include "assets/scene_loader.h"
#include "support/test_paths.h"

namespace pt {
namespace {

void expectNear(Vec3 actual, Vec3 expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(GltfLights, PunctualLightsArePlacedByTheirNodes) {
    Scene scene;
    const ImportedFile file = importGltf(test::testDataPath("gltf/lights.gltf"), 0, scene);
    ASSERT_EQ(file.lights.size(), 3u);
    for (const std::string& w : scene.warnings)
        EXPECT_EQ(w.find("KHR_lights_punctual"), std::string::npos) << w;

    const Light& bulb = file.lights[0];
    EXPECT_EQ(bulb.name, "bulb");
    EXPECT_EQ(bulb.type, LightType::Point);
    expectNear(bulb.color, {1.0f, 0.5f, 0.25f});
    EXPECT_EQ(bulb.intensity, 40.0f) << "candela, as in the file";
    EXPECT_EQ(bulb.range, 10.0f);
    expectNear(bulb.position, {1, 2, 3});

    const Light& spot = file.lights[1];
    EXPECT_EQ(spot.name, "KHR_lights_punctual.lights[1]") << "neither the light nor its node has a name";
    EXPECT_EQ(spot.type, LightType::Spot);
    expectNear(spot.position, {0, 5, 0});
    expectNear(spot.direction, {0, -1, 0});  // the node's -Z, turned by its parent
    EXPECT_NEAR(spot.innerConeDegrees, 0.2f * 180.0f / kPi, 1e-4f);
    EXPECT_NEAR(spot.outerConeDegrees, 0.6f * 180.0f / kPi, 1e-4f);

    const Light& sun = file.lights[2];
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_EQ(sun.intensity, 3.0f) << "lux";
    expectNear(sun.direction, {-1, 0, 0});
}

TEST(GltfLights, LoadedSceneKeepsItsLightsAndGetsNoFallbackSky) {
    const LoadResult result = loadScene(test::testDataPath("gltf/lights.gltf"));
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_EQ(result.scene->lights.size(), 3u);
    EXPECT_TRUE(isBlack(result.scene->environment.color)) << "lit by its own lights";
    for (const Light& light : result.scene->lights) EXPECT_EQ(light.object, 0);
}

TEST(GltfLights, NodeNamingAMissingLightIsAnError) {
    Scene scene;
    try {
        importGltf(test::testDataPath("gltf/bad_light_index.gltf"), 0, scene);
        FAIL() << "imported a node naming light 3 of 3";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "bad_light_index.gltf: nodes[2].extensions.KHR_lights_punctual.light: light 3 does not "
                     "exist (3 in the file)");
    }
}

TEST(GltfLights, TangentsAreNormalisedAndZeroOnesKept) {
    Scene scene;
    importGltf(test::testDataPath("gltf/lights.gltf"), 0, scene);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& quad = scene.meshes[0];
    ASSERT_EQ(quad.tangents.size(), quad.positions.size());
    // The importer may reorder vertices: find each by position.
    auto at = [&](Vec3 p) {
        const auto it = std::find_if(quad.positions.begin(), quad.positions.end(),
                                     [&](Vec3 q) { return length(q - p) < 1e-6f; });
        return quad.tangents[size_t(it - quad.positions.begin())];
    };
    const Vec4 first = at({0, 0, 0}), third = at({1, 1, 0});
    EXPECT_EQ(first.x, 1.0f);
    EXPECT_EQ(first.w, -1.0f);
    EXPECT_EQ(third.x, 0.0f);
    EXPECT_EQ(third.w, 0.0f) << "a zero tangent marks a vertex whose frame the renderer derives";
}

}  // namespace
}  // namespace pt
