// The editor's render thread on the CUDA backend (issue 22): while frames reach GL through
// interop, the render thread copies each published beauty into device memory of its own, and
// the window copies that into its pixel buffer without waiting for the passes that follow. The
// copy must be the published frame's beauty, pixel for pixel.
#include <cuda_runtime.h>

#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include "cuda_test_support.h"
#include "editor/editor_session.h"
#include "editor/render_worker.h"
#include "editor/scene_edits.h"
#include "render/backend/backend.h"
#include "support/scene_builder.h"

namespace pt::editor {
namespace {

TEST(CudaEditorFrames, TheDeviceCopyOfAPublishedFrameIsItsBeauty) {
    PT_REQUIRE_CUDA_DEVICE();
    EditorSession session(createBackend("cuda"));
    session.adopt(test::ballUnderLampScene(48));
    RenderWorker worker(session);
    worker.setHostFrames(false);  // as the window does once interop works
    constexpr uint32_t kTarget = 6;
    worker.edit([](EditorSession& s) {
        ViewerSettings viewer = s.document().viewer;
        viewer.targetSpp = kTarget;
        s.execute(setViewer(s.document(), viewer));
    });
    // The accumulation stops at the target: the last frame published is the beauty that stays.
    DisplayFrame frame;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (frame.stats.samplesPerPixel < kTarget && std::chrono::steady_clock::now() < deadline) {
        worker.takeFrame(frame);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_EQ(frame.stats.samplesPerPixel, kTarget) << "the accumulation did not reach its target in 60 s";
    EXPECT_TRUE(frame.rgba.empty()) << "frames carry no host pixels while interop takes them";

    std::vector<float> copied;
    uint32_t width = 0, height = 0;
    ASSERT_TRUE(worker.withDeviceFrame([&](const void* rgba, uint32_t w, uint32_t h) {
        width = w, height = h;
        copied.resize(size_t(w) * h * 4);
        ASSERT_EQ(cudaMemcpy(copied.data(), rgba, copied.size() * sizeof(float), cudaMemcpyDeviceToHost),
                  cudaSuccess);
    })) << "no device copy of the published frame";
    EXPECT_EQ(width, 48u);
    EXPECT_EQ(height, frame.height);
    std::vector<float> beauty;
    worker.withBackend([&](EditorSession& s) { s.backend().readBeauty(beauty); });
    ASSERT_EQ(beauty.size(), copied.size());
    EXPECT_EQ(std::memcmp(beauty.data(), copied.data(), beauty.size() * sizeof(float)), 0)
        << "the device copy differs from the beauty it was published with";
    double sum = 0.0;
    for (float v : copied) sum += v;
    EXPECT_GT(sum, 0.0) << "a black frame";

    // Host frames again (interop failed): no device copies are made from then on.
    worker.setHostFrames(true);
    worker.edit([](EditorSession& s) {
        Camera camera = s.document().scene.camera;
        camera.position.x += 0.1f;
        s.execute(setCamera(s.document(), camera));
    });
    ASSERT_TRUE(worker.waitForFrame(session.editSerial(), 60.0));
    ASSERT_TRUE(worker.takeFrame(frame));
    EXPECT_FALSE(frame.rgba.empty());
    EXPECT_FALSE(worker.withDeviceFrame([](const void*, uint32_t, uint32_t) {}));
}

}  // namespace
}  // namespace pt::editor
