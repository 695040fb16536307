// RenderWorker, the editor's render thread: an edit made while a pass is in flight reaches the
// backend within a sample's time, not the pass's, and closing the window during a pass returns at
// once; frames name the document they show. The viewer asks for 10^8 samples a step here, a pass of hours:
// without the interrupt the edit would miss its deadline, and the worker's destructor (the window closing,
// with the next such pass in flight) would hold the test until ctest's timeout.
#include "editor/render_worker.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "editor/scene_edits.h"
#include "render/backend/backend.h"
#include "support/scene_builder.h"

namespace pt::editor {
namespace {

using std::chrono::seconds;
using std::chrono::steady_clock;

// A session whose worker renders passes of 10^8 samples a pixel.
void startEndlessPasses(EditorSession& session, RenderWorker& worker) {
    worker.edit([](EditorSession& s) {
        ViewerSettings viewer = s.document().viewer;
        viewer.samplesPerFrame = 100'000'000;
        viewer.targetSpp = 0;
        s.execute(setViewer(s.document(), viewer));
    });
    // The first sync has run once it left its report; the endless pass follows.
    const auto deadline = steady_clock::now() + seconds(60);
    while (session.lastSync().action.empty()) {
        ASSERT_LT(steady_clock::now(), deadline) << "the first sync never ran";
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // well into the pass
}

TEST(RenderWorker, AnEditDuringAPassReachesTheBackendWithoutWaitingForIt) {
    EditorSession session(createBackend("cpu"));
    session.adopt(test::ballUnderLampScene());
    RenderWorker worker(session);
    ASSERT_NO_FATAL_FAILURE(startEndlessPasses(session, worker));

    worker.edit([](EditorSession& s) {
        Camera camera = s.document().scene.camera;
        camera.position.x += 0.2f;
        s.execute(setCamera(s.document(), camera));
    });
    // The edit's sync fills in its action; it runs once the pass in flight has stopped.
    const auto deadline = steady_clock::now() + seconds(60);
    while (session.lastEdit().action.empty()) {
        ASSERT_LT(steady_clock::now(), deadline) << "the edit waits for the pass in flight";
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_EQ(session.lastEdit().label, "Camera: position");
    EXPECT_EQ(worker.status().error, "");
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // into the next pass; then close
}

// After an open, the window must not show the previous scene's image as the new one's (it did
// for 4-6 s: issue 20, defect 7): every frame carries the document it shows, the one the
// backend had synced, so frames of the old scene still in flight say so.
TEST(RenderWorker, FramesSayWhichDocumentTheyShow) {
    EditorSession session(createBackend("cpu"));
    session.adopt(test::ballUnderLampScene(24));
    RenderWorker worker(session);
    const uint64_t first = session.documentSerial();
    DisplayFrame frame;
    const auto takeUntil = [&](uint64_t document) {
        const auto deadline = steady_clock::now() + seconds(60);
        while (steady_clock::now() < deadline) {
            if (worker.takeFrame(frame)) {
                if (frame.document == document) return true;
                EXPECT_LT(frame.document, document);
                EXPECT_EQ(frame.width, 24u) << "a frame of the new scene with the old document's serial";
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        return false;
    };
    ASSERT_TRUE(takeUntil(first));
    EXPECT_EQ(frame.width, 24u);

    worker.edit([](EditorSession& s) { s.adopt(test::ballUnderLampScene(32)); });
    const uint64_t opened = session.documentSerial();
    EXPECT_GT(opened, first);
    ASSERT_TRUE(takeUntil(opened)) << "no frame of the opened scene";
    EXPECT_EQ(frame.width, 32u) << "a frame of the old scene with the new document's serial";
}

}  // namespace
}  // namespace pt::editor

namespace pt::editor {
namespace {

// A camera edit through the worker, as the window makes it; returns its edit serial.
uint64_t nudgeCamera(RenderWorker& worker) {
    uint64_t edit = 0;
    worker.edit([&](EditorSession& s) {
        Camera camera = s.document().scene.camera;
        camera.position.y += 0.1f;
        s.execute(setCamera(s.document(), camera));
        edit = s.editSerial();
    });
    return edit;
}

// Frames say up to which edit their samples go (the window's input-to-screen measure needs it).
TEST(RenderWorker, FramesSayWhichEditsTheirSamplesInclude) {
    EditorSession session(createBackend("cpu"));
    session.adopt(test::ballUnderLampScene(16));
    RenderWorker worker(session);
    const uint64_t edit = nudgeCamera(worker);
    DisplayFrame frame;
    const auto deadline = steady_clock::now() + seconds(60);
    bool seen = false;
    while (!seen && steady_clock::now() < deadline) {
        if (worker.takeFrame(frame)) {
            EXPECT_LE(frame.edit, edit);
            seen = frame.edit == edit && frame.stats.samplesPerPixel > 0;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_TRUE(seen) << "no frame with samples of the camera edit within 60 s";
}

// The window waits a few milliseconds for an edit made in the frame it draws (issue 22): the
// wait ends with a frame of that edit to take, and times out for an edit no frame holds.
TEST(RenderWorker, WaitForFrameEndsWithAFrameOfTheEdit) {
    EditorSession session(createBackend("cpu"));
    session.adopt(test::ballUnderLampScene(16));
    RenderWorker worker(session);
    const uint64_t edit = nudgeCamera(worker);
    ASSERT_TRUE(worker.waitForFrame(edit, 60.0)) << "no frame of the edit within 60 s";
    DisplayFrame frame;
    ASSERT_TRUE(worker.takeFrame(frame));
    EXPECT_GE(frame.edit, edit);
    EXPECT_GT(frame.stats.samplesPerPixel, 0u);
    const auto start = steady_clock::now();
    EXPECT_FALSE(worker.waitForFrame(edit + 1, 0.05)) << "a frame of an edit never made";
    EXPECT_GE(steady_clock::now() - start, std::chrono::milliseconds(45));
}

}  // namespace
}  // namespace pt::editor
