// pt-render render --aov / --half: the AOV layers of the EXR, what the backend allocates for
// them (--stats' aov_bytes), and the usage errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/cli_runner.h"
#include "assets/image/exr_layers.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::runCli;

std::string cornell() { return "'" + test::projectPath("scenes/cornell.json") + "'"; }

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

std::vector<std::string> channelNames(const ExrImage& image) {
    std::vector<std::string> names;
    for (const ExrChannelData& c : image.channels) names.push_back(c.name);
    std::sort(names.begin(), names.end());
    return names;
}

TEST(RenderAovCli, WithoutAovsNoneAreAllocatedAndTheExrHoldsRgba) {
    PT_REQUIRE_OIIO();
    const std::string dir = test::tempDir();
    const std::string exr = dir + "/plain.exr", stats = dir + "/plain.json";
    const auto r =
        runCli("render " + cornell() + " -o " + exr + " --spp 1 --size 16x12 --stats " + stats + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = readJson(stats);
    EXPECT_EQ(j["aov_bytes"], 0);
    EXPECT_EQ(j["aovs"], "");
    const ExrImage image = readExrChannels(exr);
    EXPECT_EQ(channelNames(image), (std::vector<std::string>{"A", "B", "G", "R"}));
    EXPECT_EQ(image.channel("R")->type, ExrPixelType::Float);
    EXPECT_EQ(image.attribute("pt:aovs"), "");
    EXPECT_EQ(image.attribute("pt:spp"), "1");
    EXPECT_FALSE(image.attribute("pt:camera_to_world").empty());
}

TEST(RenderAovCli, AovListWritesTheirChannelsAndAllocatesOnlyThem) {
    PT_REQUIRE_OIIO();
    const std::string dir = test::tempDir();
    const std::string exr = dir + "/aovs.exr", stats = dir + "/aovs.json";
    const auto r = runCli("render " + cornell() + " -o " + exr +
                          " --spp 2 --size 16x12 --aov albedo,depth,instance_id --half --stats " + stats);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, exr + "\n");
    EXPECT_NE(r.err.find("half channels R G B A albedo.R albedo.G albedo.B depth.Z instance_id.Y"),
              std::string::npos)
        << r.err;
    const nlohmann::json j = readJson(stats);
    EXPECT_EQ(j["aovs"], "albedo,depth,instance_id");
    // Per pixel: 3 doubles of albedo, 1 of depth, 1 of the id (a backend may round up).
    EXPECT_GE(j["aov_bytes"].get<uint64_t>(), 16u * 12u * 5u * sizeof(double));
    EXPECT_LT(j["aov_bytes"].get<uint64_t>(), 16u * 12u * 8u * sizeof(double));

    const ExrImage image = readExrChannels(exr);
    EXPECT_EQ(channelNames(image), (std::vector<std::string>{"A", "B", "G", "R", "albedo.B", "albedo.G",
                                                             "albedo.R", "depth.Z", "instance_id.Y"}));
    EXPECT_EQ(image.channel("R")->type, ExrPixelType::Half);
    EXPECT_EQ(image.channel("albedo.G")->type, ExrPixelType::Half);
    EXPECT_EQ(image.channel("depth.Z")->type, ExrPixelType::Float);
    EXPECT_EQ(image.channel("instance_id.Y")->type, ExrPixelType::Float);
    EXPECT_EQ(image.attribute("pt:aovs"), "albedo,depth,instance_id");
    for (float id : image.channel("instance_id.Y")->values) {
        EXPECT_EQ(id, std::floor(id)) << "ids are whole numbers";
        EXPECT_GE(id, -1.0f);
    }
    double depth = 0.0;
    for (float d : image.channel("depth.Z")->values) depth += d;
    EXPECT_GT(depth, 0.0) << "the box is in front of the camera";
}

TEST(RenderAovCli, AllWritesEveryAov) {
    PT_REQUIRE_OIIO();
    const std::string exr = test::tempDir() + "/all.exr";
    const auto r = runCli("render " + cornell() + " -o " + exr + " --spp 1 --size 8x8 --aov all --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const ExrImage image = readExrChannels(exr);
    EXPECT_EQ(image.attribute("pt:aovs"), aovListText(kAllAovs));
    for (uint32_t i = 0; i < kAovCount; ++i) {
        for (const std::string& name : aovExrChannelNames(Aov(i)))
            EXPECT_NE(image.channel(name), nullptr) << name;
    }
}

TEST(RenderAovCli, UnknownOrMisplacedAovsAreUsageErrors) {
    const std::string out = " -o " + test::tempDir() + "/x.exr --spp 1 --size 8x8";
    struct Case {
        std::string args, needle;
    };
    const Case cases[] = {
        {"render " + cornell() + out + " --aov albedo,normals", "unknown AOV \"normals\""},
        {"render " + cornell() + out + " --aov albedo,normals", "shading_normal, geometric_normal, depth"},
        {"render " + cornell() + out + " --aov ''", "empty AOV name"},
        {"render " + cornell() + " --png " + test::tempDir() + "/x.png --aov albedo", "need -o OUT.exr"},
        {"render " + cornell() + " --png " + test::tempDir() + "/x.png --half", "need -o OUT.exr"},
    };
    for (const Case& c : cases) {
        const auto r = runCli(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\nstderr: " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\nstderr: " << r.err;
    }
}

}  // namespace
}  // namespace pt
