// The denoiser on real renders (the CPU backend; tests/render/backend/cuda compares the GPU's) and through
// `pt-render render --denoise`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "app/cli_runner.h"
#include "assets/image/exr_layers.h"
#include "assets/image/pfm_file.h"
#include "render/backend/cpu/cpu_backend.h"
#include "render/util/image_error.h"
#include "support/load_scene.h"
#include "support/test_paths.h"

namespace pt {
namespace {

Scene cornell(uint32_t size) {
    Scene scene = test::loadSceneOrFail(test::projectPath("scenes/cornell.json"));
    scene.render.width = scene.render.height = size;
    return scene;
}

// The Cornell box at 4 and 16 spp against 1024 (whose own noise is a 64th of the 16-spp image's):
// the denoised image has at most a quarter of the raw image's relMSE.
TEST(DenoisedRender, TheCornellBoxAtFewSamplesLosesMostOfItsError) {
    const Scene scene = cornell(48);
    CpuBackend reference;
    reference.sync(scene, SceneChanges::All, {});
    reference.render(1024);
    std::vector<float> truth;
    reference.readBeauty(truth);
    for (const uint32_t spp : {4u, 16u}) {
        CpuBackend backend;
        backend.setAovs(kDenoiseGuideAovs);
        backend.sync(scene, SceneChanges::All, {});
        backend.render(spp);
        std::vector<float> raw, denoised;
        backend.readBeauty(raw);
        backend.readDenoised(denoised);
        const double rawError = imageError(raw, truth).relMse,
                     denoisedError = imageError(denoised, truth).relMse;
        std::cout << "[ figures  ] Cornell 48x48, " << spp << " spp: relMSE raw " << rawError << ", denoised "
                  << denoisedError << " (" << rawError / denoisedError << "x less)\n";
        EXPECT_TRUE(allFinite(denoised));
        EXPECT_LE(denoisedError, 0.25 * rawError) << spp << " spp";
    }
}

TEST(DenoisedRender, NeedsItsGuides) {
    CpuBackend backend;
    backend.setAovs(aovBit(Aov::Albedo) | aovBit(Aov::Depth));
    backend.sync(cornell(8), SceneChanges::All, {});
    backend.render(1);
    std::vector<float> out;
    try {
        backend.readDenoised(out);
        FAIL() << "denoised without a normal guide";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("shading_normal"), std::string::npos) << e.what();
    }
}

TEST(DenoisedRender, TheCliAddsADenoisedLayerAndKeepsTheRawBeauty) {
    PT_REQUIRE_OIIO();
    const std::string dir = test::tempDir();
    const std::string exr = dir + "/denoised.exr";
    const std::string cornellPath = "'" + test::projectPath("scenes/cornell.json") + "'";
    const auto r = test::runCli("render " + cornellPath + " -o " + exr + " --spp 4 --size 24x16 --denoise");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("channels R G B A denoised.R denoised.G denoised.B"), std::string::npos) << r.err;
    const ExrImage image = readExrChannels(exr);
    EXPECT_EQ(image.attribute("pt:aovs"), "");  // the guides were accumulated, not written
    const ExrChannelData* raw = image.channel("R");
    const ExrChannelData* denoised = image.channel("denoised.R");
    ASSERT_TRUE(raw && denoised);
    // Different images (the raw one is noisy at 4 spp), of about the same brightness.
    double sumRaw = 0.0, sumDenoised = 0.0, differing = 0.0;
    for (size_t i = 0; i < raw->values.size(); ++i) {
        sumRaw += raw->values[i];
        sumDenoised += denoised->values[i];
        differing += raw->values[i] != denoised->values[i] ? 1.0 : 0.0;
    }
    EXPECT_GT(differing, 0.5 * double(raw->values.size()));
    EXPECT_NEAR(sumDenoised / sumRaw, 1.0, 0.25);
}

// -o OUT.pfm holds what the PNG would show: the raw beauty, or with --denoise the denoised one
// (the GPU machine's build, without OpenImageIO, writes its 4-spp crops so). The raw PFM is the
// backend's beauty at the same samples; AOV layers need an EXR.
TEST(DenoisedRender, APfmHoldsTheDenoisedImageWithDenoise) {
    const std::string dir = test::tempDir();
    const std::string cornellPath = "'" + test::projectPath("scenes/cornell.json") + "'";
    const std::string args = " --spp 4 --size 24x16 --quiet";
    const auto raw = test::runCli("render " + cornellPath + " -o " + dir + "/raw.pfm" + args);
    ASSERT_EQ(raw.exitCode, 0) << raw.err;
    const auto denoised =
        test::runCli("render " + cornellPath + " -o " + dir + "/denoised.pfm" + args + " --denoise");
    ASSERT_EQ(denoised.exitCode, 0) << denoised.err;
    uint32_t w = 0, h = 0;
    const std::vector<float> rawImage = readPfm(dir + "/raw.pfm", w, h);
    ASSERT_EQ(w, 24u);
    ASSERT_EQ(h, 16u);
    const std::vector<float> denoisedImage = readPfm(dir + "/denoised.pfm", w, h);
    ASSERT_EQ(denoisedImage.size(), rawImage.size());

    Scene scene = cornell(24);
    scene.render.height = 16;
    CpuBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    backend.render(4);
    std::vector<float> beauty;
    backend.readBeauty(beauty);
    ASSERT_EQ(beauty.size(), rawImage.size());
    double differing = 0.0, sumRaw = 0.0, sumDenoised = 0.0;
    for (size_t i = 0; i < beauty.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) {
            EXPECT_EQ(rawImage[i + c], beauty[i + c]) << "pixel " << i / 4;
            differing += rawImage[i + c] != denoisedImage[i + c] ? 1.0 : 0.0;
            sumRaw += rawImage[i + c];
            sumDenoised += denoisedImage[i + c];
        }
    }
    EXPECT_GT(differing, 0.5 * 3.0 * double(beauty.size() / 4)) << "the PFM of --denoise is denoised";
    EXPECT_NEAR(sumDenoised / sumRaw, 1.0, 0.25);

    const auto layers =
        test::runCli("render " + cornellPath + " -o " + dir + "/x.pfm" + args + " --aov depth");
    EXPECT_EQ(layers.exitCode, 2);
    EXPECT_NE(layers.err.find("-o OUT.exr"), std::string::npos) << layers.err;
}

}  // namespace
}  // namespace pt
