// sceneFeatures on scenes built in code: what the Cornell box uses, each material parameter
// that switches its bit on (and the values just short of it that must not), materials no
// traced instance uses, environment, thin lens, instances, spheres, morph targets, and the
// names the CLI, the stats JSON and the editor print.
#include "render/compile/scene_features.h"

#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <string>

#include "render/compile/compile_scene.h"
#include "render/integrator/camera.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using namespace feature;
using test::addMaterial;
using test::addShape;
using test::trs;

FeatureSet featuresOf(const Scene& scene) { return compileRenderScene(scene).features; }

// The default material made a smooth dielectric (roughness 0): no feature at all, where the
// default roughness of 0.5 would be a glossy specular layer.
Material smoothMaterial() {
    Material m;
    m.roughness = 0.0f;
    return m;
}

// Compares bit sets by name, so a failure says which features differ.
#define EXPECT_FEATURES(scene, expected) \
    EXPECT_EQ(describeFeatures(featuresOf(scene)), describeFeatures(expected))

// scenes/cornell.json, built the way the scene JSON loader builds it (its "diffuse", "mirror"
// and "glass" presets: assets/material_json.cpp). The CLI test checks the file itself.
Scene cornellBox() {
    Scene scene;
    scene.camera.position = {0, 0, 3.9f};
    scene.camera.verticalFovDegrees = 38.0f;
    auto preset = [](Vec3 color, const char* type) {
        Material m;
        m.baseColor = color;
        if (std::string(type) == "diffuse") {
            m.specular = 0.0f;
        } else if (std::string(type) == "mirror") {
            m.metallic = 1.0f;
            m.roughness = 0.0f;
        } else {
            m.transmission = 1.0f;
            m.roughness = 0.0f;
        }
        return m;
    };
    const uint32_t white = addMaterial(scene, "white", preset({0.73f, 0.73f, 0.73f}, "diffuse"));
    const uint32_t red = addMaterial(scene, "red", preset({0.63f, 0.065f, 0.05f}, "diffuse"));
    const uint32_t green = addMaterial(scene, "green", preset({0.14f, 0.45f, 0.091f}, "diffuse"));
    Material lightMaterial = preset({0.78f, 0.78f, 0.78f}, "diffuse");
    lightMaterial.emission = {4.25f, 3.0f, 1.0f};
    const uint32_t light = addMaterial(scene, "light", lightMaterial);
    const uint32_t mirror = addMaterial(scene, "mirror", preset({0.95f, 0.95f, 0.95f}, "mirror"));
    const uint32_t glass = addMaterial(scene, "glass", preset(Material{}.baseColor, "glass"));
    addShape(scene, ObjectKind::Quad, trs({0, -1, 0}), white, "floor");
    addShape(scene, ObjectKind::Quad, trs({0, 1, 0}, {180, 0, 0}), white, "ceiling");
    addShape(scene, ObjectKind::Quad, trs({0, 0, -1}, {90, 0, 0}), white, "back wall");
    addShape(scene, ObjectKind::Quad, trs({-1, 0, 0}, {0, 0, -90}), red, "left wall");
    addShape(scene, ObjectKind::Quad, trs({1, 0, 0}, {0, 0, 90}), green, "right wall");
    addShape(scene, ObjectKind::Quad, trs({0, 0.995f, 0}, {180, 0, 0}, {0.5f, 1, 0.4f}), light,
             "ceiling light");
    addShape(scene, ObjectKind::Box, trs({-0.36f, -0.4f, -0.25f}, {0, -30, 0}, {0.28f, 0.6f, 0.28f}), mirror,
             "mirror box");
    addShape(scene, ObjectKind::Sphere, trs({0.42f, -0.65f, 0.3f}, {0, 0, 0}, {0.35f, 0.35f, 0.35f}), glass,
             "glass sphere");
    return scene;
}

// One quad with a default material (dielectric, roughness 0.5, specular 1): no features at
// all, so each case below sees exactly the bits its one change adds. Material 1 exists but no
// instance uses it.
Scene plainQuad() {
    Scene scene;
    scene.camera.position = {0, 2, 0};
    scene.camera.up = {0, 0, -1};
    const uint32_t used = addMaterial(scene, "used", smoothMaterial());
    addMaterial(scene, "unused", smoothMaterial());
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}), used, "quad");
    return scene;
}

int32_t addTexture(Scene& scene) {
    return test::addFloatTexture(scene, 4, 2, [](uint32_t x, uint32_t y) {
        return Vec4(0.25f * float(x), 0.5f * float(y), 0.5f, 1.0f);
    });
}

TEST(SceneFeatures, CornellBoxUsesGlassMirrorEmittersSpheresAndInstances) {
    const FeatureSet f = featuresOf(cornellBox());
    // Diffuse walls are specular 0 (off the KHR_materials_specular default of 1), the box a
    // smooth conductor, the sphere smooth glass and analytic, the lamp two emissive triangles.
    EXPECT_EQ(describeFeatures(f),
              "smooth_transmission, specular_layer, metal, emissive_triangles, "
              "multiple_instances, spheres");
    EXPECT_EQ(f, kSmoothTransmission | kSpecularLayer | kMetal | kEmissiveTriangles | kMultipleInstances |
                     kSpheres);
    // What a diffuse-and-glass box must not pay for.
    EXPECT_EQ(f & (kTextures | kNormalMap | kTransparency | kRoughTransmission | kVolume | kClearcoat |
                   kImageEnvironment | kConstantEnvironment | kThinLens | kPunctualLights | kSphereLights |
                   kMorphTargets | kAovs | kBruteForce),
              0u);
}

TEST(SceneFeatures, APlainQuadUsesNothing) {
    EXPECT_EQ(featuresOf(plainQuad()), 0u);
    EXPECT_EQ(describeFeatures(featuresOf(plainQuad())), "none");
}

struct MaterialCase {
    const char* what;
    std::function<void(Material&, Scene&)> change;
    FeatureSet expected;
};

// Each case changes material 0 (used by the quad) and expects exactly these features; the same
// change on material 1, which no instance uses, must add nothing.
std::vector<MaterialCase> materialCases() {
    return {
        {"base color texture", [](Material& m, Scene& s) { m.baseColorTexture.texture = addTexture(s); },
         kBaseColorTexture},
        {"metallic-roughness texture",
         [](Material& m, Scene& s) { m.metallicRoughnessTexture.texture = addTexture(s); },
         kMetallicRoughnessTexture},
        {"normal map", [](Material& m, Scene& s) { m.normalTexture.texture = addTexture(s); }, kNormalMap},
        {"emissive texture on a black emission",
         [](Material& m, Scene& s) { m.emissiveTexture.texture = addTexture(s); }, 0u},
        {"emissive texture",
         [](Material& m, Scene& s) {
             m.emissiveTexture.texture = addTexture(s);
             m.emission = {1, 1, 1};
         },
         kEmissiveTexture | kEmissiveTriangles},
        {"emission",
         [](Material& m, Scene&) {
             m.emission = {2, 2, 2};
         },
         kEmissiveTriangles},
        {"transmission texture", [](Material& m, Scene& s) { m.transmissionTexture.texture = addTexture(s); },
         kTransmissionTexture | kSmoothTransmission},
        {"alpha mask",
         [](Material& m, Scene&) {
             m.alphaMode = AlphaMode::Mask;
             m.alpha = 0.25f;
         },
         kAlphaMask},
        {"alpha mask over its cutoff",
         [](Material& m, Scene&) {
             m.alphaMode = AlphaMode::Mask;
             m.alpha = 0.75f;
         },
         0u},
        {"alpha blend",
         [](Material& m, Scene&) {
             m.alphaMode = AlphaMode::Blend;
             m.alpha = 0.5f;
         },
         kAlphaBlend},
        {"alpha blend, opaque", [](Material& m, Scene&) { m.alphaMode = AlphaMode::Blend; }, 0u},
        {"single-sided", [](Material& m, Scene&) { m.doubleSided = 0; }, kBackfaceCulling},
        {"smooth transmission",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
         },
         kSmoothTransmission},
        {"rough transmission (its specular reflection is glossy too)",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.5f;
         },
         kRoughTransmission | kGlossyReflection},
        {"rough dielectric", [](Material& m, Scene&) { m.roughness = 0.5f; }, kGlossyReflection},
        {"rough metal",
         [](Material& m, Scene&) {
             m.metallic = 1.0f;
             m.roughness = 0.3f;
         },
         kMetal | kGlossyReflection},
        {"rough, but no specular layer",
         [](Material& m, Scene&) {
             m.roughness = 0.5f;
             m.specular = 0.0f;
         },
         kSpecularLayer},
        {"nearly smooth (below GGX's smooth alpha)", [](Material& m, Scene&) { m.roughness = 1e-3f; }, 0u},
        {"single-sided glass (never culled)",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
             m.doubleSided = 0;
         },
         kSmoothTransmission},
        {"transmission on a metal",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.metallic = 1.0f;
         },
         kMetal},
        {"volume",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
             m.thickness = 1.0f;
             m.attenuationColor = {0.5f, 0.8f, 0.9f};
             m.attenuationDistance = 2.0f;
         },
         kSmoothTransmission | kVolume},
        {"volume without attenuation",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
             m.thickness = 1.0f;
         },
         kSmoothTransmission},
        {"scattering volume",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
             m.thickness = 1.0f;
             m.attenuationColor = {0.5f, 0.5f, 0.5f};
             m.attenuationDistance = 2.0f;
             m.scatterColor = {0.5f, 0.5f, 0.5f};
         },
         kSmoothTransmission | kVolume | kScatteringMedia},
        {"scatter colour without attenuation (nothing to scatter)",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
             m.thickness = 1.0f;
             m.scatterColor = {0.5f, 0.5f, 0.5f};
         },
         kSmoothTransmission},
        {"subsurface",
         [](Material& m, Scene&) {
             m.roughness = 0.0f;
             m.subsurface = 0.5f;
         },
         kSmoothTransmission | kVolume | kScatteringMedia},
        {"index-matched absorbing volume",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
             m.ior = 1.0f;
             m.thickness = 1.0f;
             m.attenuationDistance = 2.0f;
         },
         kSmoothTransmission | kVolume | kIndexMatchedBoundaries},
        {"index 1 but thin-walled: no volume to bound",
         [](Material& m, Scene&) {
             m.transmission = 1.0f;
             m.roughness = 0.0f;
             m.ior = 1.0f;
         },
         kSmoothTransmission},
        {"clearcoat", [](Material& m, Scene&) { m.clearcoat = 1.0f; }, kClearcoat},
        {"specular 0.5", [](Material& m, Scene&) { m.specular = 0.5f; }, kSpecularLayer},
        {"specular colour",
         [](Material& m, Scene&) {
             m.specularColor = {1.0f, 0.5f, 1.0f};
         },
         kSpecularLayer},
        {"metallic 1", [](Material& m, Scene&) { m.metallic = 1.0f; }, kMetal},
    };
}

TEST(SceneFeatures, EachMaterialParameterSetsItsBit) {
    for (const MaterialCase& c : materialCases()) {
        Scene scene = plainQuad();
        c.change(scene.materials[0].params, scene);
        EXPECT_EQ(describeFeatures(featuresOf(scene)), describeFeatures(c.expected)) << c.what;
    }
}

TEST(SceneFeatures, AMaterialNoInstanceUsesAddsNothing) {
    for (const MaterialCase& c : materialCases()) {
        Scene scene = plainQuad();
        c.change(scene.materials[1].params, scene);
        EXPECT_EQ(describeFeatures(featuresOf(scene)), "none") << c.what;
    }
    // A hidden instance is not traced: its material costs nothing either.
    Scene scene = plainQuad();
    scene.materials[1].params.clearcoat = 1.0f;
    const uint32_t hidden = addShape(scene, ObjectKind::Quad, trs({0, 1, 0}), 1, "hidden");
    scene.instances[hidden].visible = false;
    EXPECT_FEATURES(scene, 0u);
    scene.instances[hidden].visible = true;
    EXPECT_FEATURES(scene, kClearcoat | kMultipleInstances);
}

TEST(SceneFeatures, EnvironmentBlackConstantOrImage) {
    Scene scene = plainQuad();
    EXPECT_FEATURES(scene, 0u);
    scene.environment.color = {0.0f, 0.0f, 0.25f};
    EXPECT_FEATURES(scene, kConstantEnvironment);
    scene.environment.texture = addTexture(scene);  // the image replaces the colour
    EXPECT_FEATURES(scene, kImageEnvironment);
}

TEST(SceneFeatures, ApertureMakesAThinLens) {
    Scene scene = plainQuad();
    scene.camera.apertureRadius = 0.05f;
    EXPECT_FEATURES(scene, kThinLens);
}

TEST(SceneFeatures, LightsOtherThanTriangles) {
    Scene scene = plainQuad();
    test::addLight(scene, LightType::Point, {1, 1, 1}, 10.0f, {0, 1, 0});
    EXPECT_FEATURES(scene, kPunctualLights);

    scene = plainQuad();
    Material glow = smoothMaterial();
    glow.emission = {3, 3, 3};
    const uint32_t lamp = addMaterial(scene, "lamp", glow);
    addShape(scene, ObjectKind::Sphere, trs({0, 1, 0}, {0, 0, 0}, {0.1f, 0.1f, 0.1f}), lamp, "lamp");
    EXPECT_FEATURES(scene, kSphereLights | kSpheres | kMultipleInstances);
}

TEST(SceneFeatures, OneInstanceOrMore) {
    Scene scene = plainQuad();
    EXPECT_FEATURES(scene, 0u);
    addShape(scene, ObjectKind::Quad, trs({0, 1, 0}), 0, "second");
    EXPECT_FEATURES(scene, kMultipleInstances);
}

TEST(SceneFeatures, SpheresAreAnalyticPrimitives) {
    Scene scene;
    addMaterial(scene, "m", smoothMaterial());
    addShape(scene, ObjectKind::Sphere, trs({0, 0, 0}), 0, "ball");
    EXPECT_FEATURES(scene, kSpheres);
    scene = Scene{};
    addMaterial(scene, "m", smoothMaterial());
    addShape(scene, ObjectKind::Box, trs({0, 0, 0}), 0, "box");  // triangles
    EXPECT_FEATURES(scene, 0u);
}

TEST(SceneFeatures, MorphTargets) {
    Scene scene = plainQuad();
    Mesh& quad = scene.meshes[scene.instances[0].mesh];
    MorphTarget target;
    target.name = "lift";
    target.positionDeltas.assign(quad.positions.size(), Vec3(0.0f, 0.25f, 0.0f));
    quad.basePositions = quad.positions;
    quad.morphTargets.push_back(target);
    quad.morphWeights = {0.0f};
    quad.defaultMorphWeights = {0.0f};
    EXPECT_FEATURES(scene, kMorphTargets);
}

TEST(SceneFeatures, UpdateFeaturesFollowsAnEditWithoutACompile) {
    Scene scene = plainQuad();
    CompiledScene compiled = compileRenderScene(scene);
    EXPECT_EQ(compiled.features, 0u);
    scene.environment.color = {1, 1, 1};
    compileLights(scene, compiled);
    scene.camera.apertureRadius = 0.1f;
    compiled.camera = makeRenderCamera(scene.camera, scene.render.width, scene.render.height);
    updateFeatures(scene, compiled);
    EXPECT_EQ(describeFeatures(compiled.features), describeFeatures(kConstantEnvironment | kThinLens));
    EXPECT_EQ(compiled.view().features, compiled.features);
}

TEST(SceneFeatureNames, OneDistinctSnakeCaseNamePerBitInBitOrder) {
    std::set<std::string> seen;
    for (uint32_t i = 0; i < kCount; ++i) {
        const std::string name = featureName(FeatureSet{1} << i);
        EXPECT_NE(name, "unknown") << "bit " << i;
        EXPECT_TRUE(seen.insert(name).second) << name << " names two bits";
        EXPECT_EQ(name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_"), std::string::npos) << name;
        EXPECT_EQ(featureNames(FeatureSet{1} << i), std::vector<std::string>{name});
    }
    EXPECT_EQ(featureNames(kAllFeatures).size(), size_t(kCount));
    EXPECT_EQ(std::string(featureName(kClearcoat | kMetal)), "unknown");  // not one bit
    const FeatureSet pastLast = FeatureSet{1} << kCount;
    EXPECT_EQ(std::string(featureName(pastLast)), "unknown");
    EXPECT_TRUE(featureNames(0u).empty());
    EXPECT_TRUE(featureNames(pastLast).empty()) << "bits past kCount name nothing";
}

TEST(SceneFeatureNames, DescribeJoinsTheNamesOrSaysNone) {
    EXPECT_EQ(describeFeatures(0u), "none");
    EXPECT_EQ(describeFeatures(kMetal), "metal");
    EXPECT_EQ(describeFeatures(kMetal | kClearcoat | kBaseColorTexture),
              "base_color_texture, clearcoat, metal");
    EXPECT_EQ(featureName(kAovs), std::string("aovs"));
    EXPECT_EQ(featureName(kBruteForce), std::string("brute_force"));
    // Every set round-trips: its names, mapped back to bits, give the set again.
    for (const FeatureSet f : {FeatureSet{0}, kTextures, kTransparency | kVolume, kAllFeatures}) {
        FeatureSet back = 0;
        for (const std::string& name : featureNames(f)) {
            for (uint32_t i = 0; i < kCount; ++i) {
                if (name == featureName(FeatureSet{1} << i)) back |= FeatureSet{1} << i;
            }
        }
        EXPECT_EQ(back, f) << describeFeatures(f);
        std::string joined;
        for (const std::string& name : featureNames(f)) joined += (joined.empty() ? "" : ", ") + name;
        EXPECT_EQ(describeFeatures(f), joined.empty() ? "none" : joined);
    }
}

}  // namespace
}  // namespace pt
