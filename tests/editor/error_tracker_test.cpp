// ErrorTracker: the figures equal imageError's, points are log-spaced in render time, a
// restarted accumulation restarts the curve, a size mismatch is reported, references load with
// their noise estimate; and RenderWorker measures a falling curve while it renders.
#include "editor/error_tracker.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "assets/image/image_write.h"
#include "assets/input_error.h"
#include "editor/render_worker.h"
#include "render/backend/backend.h"
#include "support/scene_builder.h"

namespace pt::editor {
namespace {

std::vector<float> flatImage(uint32_t pixels, float value) {
    std::vector<float> rgba(size_t(pixels) * 4, value);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 1.0f;
    return rgba;
}

std::shared_ptr<ReferenceImage> flatReference(uint32_t width, uint32_t height, float value) {
    auto reference = std::make_shared<ReferenceImage>();
    reference->width = width;
    reference->height = height;
    reference->rgba = flatImage(width * height, value);
    return reference;
}

TEST(ErrorTracker, PointsCarryTheImageErrorAgainstTheReference) {
    ErrorTracker tracker;
    tracker.setReference(flatReference(4, 2, 0.5f));
    ASSERT_TRUE(tracker.due(0.1, 1, 4, 2));
    const std::vector<float> image = flatImage(8, 0.6f);
    tracker.add(0.1, 1, image);
    const std::vector<ErrorPoint> curve = tracker.curve();
    ASSERT_EQ(curve.size(), 1u);
    EXPECT_EQ(curve[0].spp, 1u);
    EXPECT_DOUBLE_EQ(curve[0].seconds, 0.1);
    const ImageError expected = imageError(image, tracker.reference()->rgba);
    EXPECT_DOUBLE_EQ(curve[0].error.relMse, expected.relMse);
    EXPECT_DOUBLE_EQ(curve[0].error.rmse, expected.rmse);
    EXPECT_NEAR(curve[0].error.relMse, 0.01 / (0.25 + kRelativeErrorEpsilon), 1e-6);
}

TEST(ErrorTracker, MeasuresAtLogSpacedTimes) {
    ErrorTracker tracker;
    tracker.setReference(flatReference(2, 2, 0.5f));
    const std::vector<float> image = flatImage(4, 0.5f);
    ASSERT_TRUE(tracker.due(1.0, 1, 2, 2));
    tracker.add(1.0, 1, image);
    EXPECT_FALSE(tracker.due(1.3, 2, 2, 2)) << "closer than 10^(1/8) to the last point";
    EXPECT_TRUE(tracker.due(1.34, 2, 2, 2));
    tracker.add(1.34, 2, image);
    EXPECT_EQ(tracker.curve().size(), 2u);
}

TEST(ErrorTracker, ARestartedAccumulationStartsANewCurve) {
    ErrorTracker tracker;
    tracker.setReference(flatReference(2, 2, 0.5f));
    const std::vector<float> image = flatImage(4, 0.4f);
    ASSERT_TRUE(tracker.due(1.0, 8, 2, 2));
    tracker.add(1.0, 8, image);
    // Fewer samples than the last point: the backend was reset without the worker knowing.
    EXPECT_TRUE(tracker.due(0.05, 1, 2, 2));
    EXPECT_TRUE(tracker.curve().empty());
    tracker.add(0.05, 1, image);
    tracker.restart();
    EXPECT_TRUE(tracker.curve().empty());
}

TEST(ErrorTracker, ASizeMismatchIsReportedAndNotMeasured) {
    ErrorTracker tracker;
    EXPECT_FALSE(tracker.due(1.0, 1, 4, 4)) << "no reference";
    tracker.setReference(flatReference(8, 4, 0.5f));
    EXPECT_FALSE(tracker.due(1.0, 1, 4, 4));
    EXPECT_EQ(tracker.problem(), "the reference is 8x4, the render 4x4");
    EXPECT_TRUE(tracker.due(1.0, 1, 8, 4));
    EXPECT_EQ(tracker.problem(), "");
    tracker.add(1.0, 1, flatImage(16, 0.5f));  // the wrong size: ignored, not a crash
    EXPECT_TRUE(tracker.curve().empty());
}

TEST(ErrorTracker, LoadsAReferenceWithItsNoiseEstimate) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "pt_error_tracker_test";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "reference.exr").string();
    try {
        writeExr(path, 3, 2, flatImage(6, 0.25f), {{"pt:noise_relmse", "0.0025"}});
    } catch (const InputError& e) {
        GTEST_SKIP() << "no EXR writer in this build: " << e.what();
    }
    ErrorTracker tracker;
    tracker.load(path);
    const auto reference = tracker.reference();
    ASSERT_TRUE(reference);
    EXPECT_EQ(reference->width, 3u);
    EXPECT_EQ(reference->height, 2u);
    EXPECT_FLOAT_EQ(reference->rgba[0], 0.25f);
    EXPECT_DOUBLE_EQ(reference->noiseRelMse, 0.0025);
    const std::string missing = (dir / "missing.exr").string();
    try {
        tracker.load(missing);
        FAIL() << "loading a missing file should throw";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    EXPECT_EQ(tracker.reference(), reference) << "a failed load keeps the reference";
}

// The editor's render thread measures the error as it accumulates: against a high-spp render
// of the same scene, the error at 16 or more times the samples of the first point is lower.
TEST(ErrorTracker, TheRenderThreadMeasuresAFallingCurve) {
    Scene scene = test::ballUnderLampScene();
    scene.environment.color = {0.05f, 0.05f, 0.05f};

    auto reference = std::make_shared<ReferenceImage>();
    {
        std::unique_ptr<Backend> backend = createBackend("cpu");
        backend->sync(scene, SceneChanges::All, {});
        backend->render(512);
        backend->readBeauty(reference->rgba);
        reference->width = backend->width();
        reference->height = backend->height();
    }

    EditorSession session(createBackend("cpu"));
    session.adopt(scene);
    RenderWorker worker(session);
    worker.errors().setReference(reference);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::vector<ErrorPoint> curve;
    for (;;) {
        curve = worker.errors().curve();
        if (curve.size() >= 2 && curve.back().spp >= 16 * curve.front().spp) break;
        ASSERT_LT(std::chrono::steady_clock::now(), deadline)
            << "the curve has " << curve.size() << " points";
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    for (size_t i = 1; i < curve.size(); ++i) {
        EXPECT_GE(curve[i].seconds, curve[i - 1].seconds * ErrorTracker::kSpacing * 0.999);
        EXPECT_GT(curve[i].spp, curve[i - 1].spp);
    }
    EXPECT_LT(curve.back().error.relMse, curve.front().error.relMse)
        << "spp " << curve.front().spp << " -> " << curve.back().spp;
}

}  // namespace
}  // namespace pt::editor
