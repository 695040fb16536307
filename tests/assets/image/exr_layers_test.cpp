// Layered EXR (assets/exr_layers.h): every AOV of the CPU backend written beside the beauty and
// read back through OpenImageIO, in float and in half, with the channel names, pixel types and
// metadata the header promises; the AOV list parser; the camera attributes.
#include "assets/image/exr_layers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "assets/image/image_metadata.h"
#include "assets/input_error.h"
#include "render/backend/cpu/cpu_backend.h"
#include "support/aov_scenes.h"
#include "support/test_paths.h"

namespace pt {
namespace {

// The scheme of exr_layers.h, spelled out: each AOV's channels and whether they stay float
// in a half file.
struct ExpectedLayer {
    Aov aov;
    std::vector<std::string> channels;
    bool alwaysFloat;
};

const std::vector<ExpectedLayer>& expectedLayers() {
    static const std::vector<ExpectedLayer> layers = {
        {Aov::Albedo, {"albedo.R", "albedo.G", "albedo.B"}, false},
        {Aov::ShadingNormal, {"shading_normal.X", "shading_normal.Y", "shading_normal.Z"}, false},
        {Aov::GeometricNormal, {"geometric_normal.X", "geometric_normal.Y", "geometric_normal.Z"}, false},
        {Aov::Depth, {"depth.Z"}, true},
        {Aov::Position, {"position.X", "position.Y", "position.Z"}, true},
        {Aov::Uv, {"uv.U", "uv.V"}, false},
        {Aov::Roughness, {"roughness.Y"}, false},
        {Aov::Metallic, {"metallic.Y"}, false},
        {Aov::Emission, {"emission.R", "emission.G", "emission.B"}, false},
        {Aov::InstanceId, {"instance_id.Y"}, true},
        {Aov::MaterialId, {"material_id.Y"}, true},
        {Aov::BvhCost, {"bvh_cost.nodes", "bvh_cost.primitives"}, false},
        {Aov::SampleCount, {"sample_count.Y"}, true},
        {Aov::Variance, {"variance.Y"}, false},
        {Aov::Alpha, {"alpha.A"}, false},
    };
    return layers;
}

// The analytic sphere rendered with every AOV on: the beauty and each AOV as readAov gives it.
struct Rendered {
    Scene scene;
    LayeredExr exr;
};

Rendered renderAllAovs(ExrPixelType precision) {
    Rendered r{test::analyticSphereScene(20, 16), {}};
    CpuBackend backend;
    backend.setAovs(kAllAovs);
    backend.sync(r.scene, SceneChanges::All, {});
    backend.render(3);
    EXPECT_EQ(backend.aovs(), kAllAovs);
    r.exr = {backend.width(), backend.height(), {}, readAovImages(backend, kAllAovs), precision, {}, {}};
    backend.readBeauty(r.exr.beauty);
    r.exr.metadata = renderMetadata(3, "0.25", backend.name(), "sphere.json", "pt tests");
    const ImageMetadata camera = cameraMetadata(r.scene.camera, r.exr.width, r.exr.height);
    r.exr.metadata.insert(r.exr.metadata.end(), camera.begin(), camera.end());
    r.exr.metadata.insert(r.exr.metadata.end(),
                          {{"pt:ocio_config", "/configs/studio.ocio"}, {"pt:ocio_view", "AgX"}});
    return r;
}

// What a value reads back as: exact in float; in half, rounded to 11 significant bits (or to
// the subnormal spacing 2^-24 near 0).
void expectStored(float read, float written, ExrPixelType type, const std::string& what) {
    if (type == ExrPixelType::Float) {
        ASSERT_EQ(read, written) << what;
    } else {
        ASSERT_NEAR(read, written, std::fabs(written) * 0x1p-11f + 0x1p-25f) << what;
    }
}

void expectRoundTrip(ExrPixelType precision) {
    const Rendered r = renderAllAovs(precision);
    const std::string path = test::tempDir() + (precision == ExrPixelType::Half ? "/half.exr" : "/float.exr");
    writeLayeredExr(path, r.exr);
    const ExrImage read = readExrChannels(path);
    ASSERT_EQ(read.width, 20u);
    ASSERT_EQ(read.height, 16u);
    const size_t pixels = 20u * 16u;

    std::vector<std::string> expectedNames = {"R", "G", "B", "A"};
    for (const ExpectedLayer& layer : expectedLayers()) {
        expectedNames.insert(expectedNames.end(), layer.channels.begin(), layer.channels.end());
    }
    ASSERT_EQ(read.channels.size(), expectedNames.size());
    for (const std::string& name : expectedNames) ASSERT_NE(read.channel(name), nullptr) << name;
    for (size_t c = 0; c < 4; ++c) {
        const ExrChannelData& channel = *read.channel(expectedNames[c]);
        EXPECT_EQ(channel.type, precision) << channel.name;
        for (size_t i = 0; i < pixels; ++i) {
            expectStored(channel.values[i], r.exr.beauty[i * 4 + c], precision, channel.name);
        }
    }
    for (const ExpectedLayer& layer : expectedLayers()) {
        const AovImage& image = r.exr.aovs.at(size_t(layer.aov));
        ASSERT_EQ(image.aov, layer.aov);
        EXPECT_EQ(aovExrChannelNames(layer.aov), layer.channels);
        for (size_t c = 0; c < layer.channels.size(); ++c) {
            const ExrChannelData& channel = *read.channel(layer.channels[c]);
            const ExrPixelType type = layer.alwaysFloat ? ExrPixelType::Float : precision;
            EXPECT_EQ(channel.type, type) << channel.name;
            for (size_t i = 0; i < pixels; ++i) {
                expectStored(channel.values[i], image.rgba[i * 4 + c], type,
                             channel.name + " pixel " + std::to_string(i));
            }
        }
    }
    // Ids are exact, misses included.
    const std::vector<float>& ids = read.channel("instance_id.Y")->values;
    EXPECT_NE(std::find(ids.begin(), ids.end(), -1.0f), ids.end()) << "some camera rays miss the sphere";
    EXPECT_NE(std::find(ids.begin(), ids.end(), 0.0f), ids.end()) << "some hit it";
    EXPECT_EQ(read.channel("sample_count.Y")->values[0], 3.0f);

    EXPECT_EQ(read.attribute("pt:aovs"), aovListText(kAllAovs));
    EXPECT_EQ(read.attribute("pt:spp"), "3");
    EXPECT_EQ(read.attribute("pt:render_seconds"), "0.25");
    EXPECT_EQ(read.attribute("pt:scene"), "sphere.json");
    EXPECT_EQ(read.attribute("Software"), "pt tests");
    EXPECT_EQ(read.attribute("pt:ocio_config"), "/configs/studio.ocio");
    EXPECT_EQ(read.attribute("pt:ocio_view"), "AgX");
    EXPECT_EQ(read.attribute("pt:camera_position"), "0 0.5 4");
    EXPECT_EQ(read.attribute("pt:camera_vertical_fov_deg"), "40");
    EXPECT_FALSE(read.attribute("pt:camera_to_world").empty());
}

TEST(ExrLayers, EveryAovRoundTripsInFloat) {
    PT_REQUIRE_OIIO();
    expectRoundTrip(ExrPixelType::Float);
}

TEST(ExrLayers, EveryAovRoundTripsInHalfWithIdsDepthAndPositionInFloat) {
    PT_REQUIRE_OIIO();
    expectRoundTrip(ExrPixelType::Half);
}

// A sun seen directly is brighter than half can hold: it saturates instead of becoming +inf.
TEST(ExrLayers, HalfChannelsSaturateInsteadOfOverflowing) {
    PT_REQUIRE_OIIO();
    const std::vector<float> rgba = {1e6f, -1e6f, 65504.0f, 1.0f};
    const std::vector<float> depth = {1e6f, 0.0f, 0.0f, 1.0f};
    const std::string path = test::tempDir() + "/sun.exr";
    writeLayeredExr(path, {1, 1, rgba, {{Aov::Depth, depth}}, ExrPixelType::Half, {}, {}});
    const ExrImage read = readExrChannels(path);
    EXPECT_EQ(read.channel("R")->values[0], 65504.0f);
    EXPECT_EQ(read.channel("G")->values[0], -65504.0f);
    EXPECT_EQ(read.channel("B")->values[0], 65504.0f);
    EXPECT_EQ(read.channel("depth.Z")->values[0], 1e6f) << "float channels keep their values";
}

TEST(ExrLayers, WithoutAovsTheFileHoldsTheBeautyAlone) {
    PT_REQUIRE_OIIO();
    const std::vector<float> rgba = {0.5f, 1.0f, 2.0f, 1.0f, 3.0f, 4.0f, 5.0f, 1.0f};
    const std::string path = test::tempDir() + "/beauty.exr";
    writeLayeredExr(path, {2, 1, rgba, {}, ExrPixelType::Half, {}, {}});
    const ExrImage read = readExrChannels(path);
    ASSERT_EQ(read.channels.size(), 4u);
    EXPECT_EQ(read.channels[0].name, "R");
    EXPECT_EQ(read.channels[3].name, "A");
    EXPECT_EQ(read.channel("G")->values, (std::vector<float>{1.0f, 4.0f}));
    EXPECT_EQ(read.channel("G")->type, ExrPixelType::Half);
    EXPECT_EQ(read.attribute("pt:aovs"), "");
}

// The beauty of a layered file is what tools reading RGBA (converge references) get, whatever
// channels sort before it.
TEST(ExrLayers, ReadImageRgbaTakesTheBeautyOfALayeredFile) {
    PT_REQUIRE_OIIO();
    const std::vector<float> beauty = {0.25f, 0.5f, 0.75f, 1.0f};
    const std::vector<float> albedo = {9.0f, 8.0f, 7.0f, 1.0f};
    const std::string path = test::tempDir() + "/layered.exr";
    writeLayeredExr(path, {1, 1, beauty, {{Aov::Albedo, albedo}}, ExrPixelType::Float, {}, {}});
    uint32_t w = 0, h = 0;
    EXPECT_EQ(readImageRgba(path, w, h), beauty);
}

TEST(ExrLayers, BadImagesGiveInputErrorsNamingTheFile) {
    const std::string path = test::tempDir() + "/bad.exr";
    const std::vector<float> one = {1.0f, 1.0f, 1.0f, 1.0f};
    auto message = [&](const LayeredExr& exr) -> std::string {
        try {
            writeLayeredExr(path, exr);
        } catch (const InputError& e) {
            return e.what();
        }
        return "(no error)";
    };
    EXPECT_NE(
        message({1, 1, one, {{Aov::Depth, {1.0f}}}, ExrPixelType::Float, {}, {}}).find(path + ": AOV depth"),
        std::string::npos);
    EXPECT_NE(message({1, 1, one, {{Aov::Depth, one}, {Aov::Depth, one}}, ExrPixelType::Float, {}, {}})
                  .find("twice"),
              std::string::npos);
    EXPECT_NE(message({2, 1, one, {}, ExrPixelType::Float, {}, {}}).find(path), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(path));
    // A valid image: written where OpenImageIO is, else refused with the reason.
    const std::string valid = message({1, 1, one, {}, ExrPixelType::Float, {}, {}});
    if (PT_TEST_HAVE_OIIO) {
        EXPECT_EQ(valid, "(no error)");
    } else {
        EXPECT_NE(valid.find("OpenImageIO"), std::string::npos) << valid;
    }
    const std::string noFolder = test::tempDir() + "/no/such/folder.exr";
    try {
        writeLayeredExr(noFolder, {1, 1, one, {}, ExrPixelType::Float, {}, {}});
        ADD_FAILURE() << "wrote into a missing folder";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(noFolder), std::string::npos) << e.what();
    }
}

TEST(ExrLayers, AovListsParseByNameAndListTheValidNamesOnError) {
    EXPECT_EQ(parseAovList("albedo,depth"), aovBit(Aov::Albedo) | aovBit(Aov::Depth));
    EXPECT_EQ(parseAovList("all"), kAllAovs);
    EXPECT_EQ(parseAovList("variance,all"), kAllAovs);
    EXPECT_EQ(aovListText(aovBit(Aov::Uv) | aovBit(Aov::Albedo)), "albedo,uv");
    EXPECT_EQ(aovListText(0), "");
    for (const char* bad : {"", "albedo,", "albedo,normal", "Albedo"}) {
        try {
            parseAovList(bad);
            ADD_FAILURE() << "\"" << bad << "\" parsed";
        } catch (const InputError& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("shading_normal, geometric_normal"), std::string::npos) << m;
            EXPECT_NE(m.find("variance"), std::string::npos) << m;
        }
    }
}

std::vector<double> numbers(const std::string& text) {
    std::istringstream in(text);
    std::vector<double> out;
    for (double v; in >> v;) out.push_back(v);
    return out;
}

TEST(ExrLayers, CameraAttributesDescribeTheView) {
    Camera camera;
    camera.position = {1.0f, 2.0f, 3.0f};
    camera.lookAt = {1.0f, 2.0f, -1.0f};  // straight down -z: the camera-to-world is a translation
    camera.verticalFovDegrees = 30.0f;
    camera.apertureRadius = 0.05f;
    std::map<std::string, std::string> m;
    for (const auto& [key, value] : cameraMetadata(camera, 64, 32)) m[key] = value;
    EXPECT_EQ(m["pt:camera_position"], "1 2 3");
    EXPECT_EQ(m["pt:camera_look_at"], "1 2 -1");
    EXPECT_EQ(m["pt:camera_up"], "0 1 0");
    EXPECT_EQ(m["pt:camera_vertical_fov_deg"], "30");
    EXPECT_EQ(float(numbers(m["pt:camera_aperture_radius"]).at(0)), 0.05f) << "9 digits: the float survives";
    EXPECT_EQ(m["pt:camera_focus_distance"], "4") << "the look-at distance where the scene sets none";
    const std::vector<double> expected = {1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
    const std::vector<double> matrix = numbers(m["pt:camera_to_world"]);
    ASSERT_EQ(matrix.size(), 16u);
    for (size_t i = 0; i < 16; ++i) EXPECT_NEAR(matrix[i], expected[i], 1e-6) << i;

    // Looking along +x: the camera's -z column is +x, its x column -z... as makeRenderCamera.
    camera.lookAt = {5.0f, 2.0f, 3.0f};
    camera.focusDistance = 2.5f;
    m.clear();
    for (const auto& [key, value] : cameraMetadata(camera, 64, 32)) m[key] = value;
    EXPECT_EQ(m["pt:camera_focus_distance"], "2.5");
    const std::vector<double> turned = numbers(m["pt:camera_to_world"]);
    ASSERT_EQ(turned.size(), 16u);
    EXPECT_NEAR(turned[2], -1.0, 1e-6);  // z axis, x component: -forward = -x
    EXPECT_NEAR(turned[8], 1.0, 1e-6);   // x axis (right), z component: +z
    EXPECT_NEAR(turned[5], 1.0, 1e-6);   // y axis stays up
}

}  // namespace
}  // namespace pt
