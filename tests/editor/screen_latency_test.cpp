// ScreenLatency (issue 22): an edit is measured from the input behind it to the first swapped
// frame whose samples include it; frames of older edits, and frames without samples (a reset
// accumulation), end no wait. EditorSession numbers the edits that change what is rendered
// (RenderWorker's frames say up to which edit their samples go: render_worker_test.cpp).
#include "editor/screen_latency.h"

#include <gtest/gtest.h>

#include <chrono>

#include "editor/editor_session.h"
#include "editor/scene_edits.h"
#include "render/backend/backend.h"
#include "support/scene_builder.h"

namespace pt::editor {
namespace {

using Clock = ScreenLatency::Clock;
using std::chrono::milliseconds;

const Clock::time_point t0 = Clock::now();
Clock::time_point at(int ms) { return t0 + milliseconds(ms); }

TEST(ScreenLatency, AnEditWaitsForAFrameWithSamplesOfIt) {
    ScreenLatency latency;
    latency.editApplied(3, "Edit material red", at(0), at(2));
    EXPECT_FALSE(latency.resolves(2, 8)) << "a frame of the edits before it";
    EXPECT_TRUE(latency.frameSwapped(2, 8, at(10)).empty());
    EXPECT_FALSE(latency.resolves(3, 0)) << "the edit's reset accumulation, no sample yet";
    EXPECT_TRUE(latency.frameSwapped(3, 0, at(12)).empty());
    ASSERT_TRUE(latency.resolves(3, 1));
    const std::vector<ScreenLatencyRecord> shown = latency.frameSwapped(3, 1, at(25));
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_EQ(shown[0].label, "Edit material red");
    EXPECT_DOUBLE_EQ(shown[0].inputToSwapMillis(), 25.0);
    EXPECT_DOUBLE_EQ(shown[0].inputToApplyMillis(), 2.0);
    EXPECT_EQ(shown[0].samplesPerPixel, 1u);
    EXPECT_EQ(latency.pending(), 0u);
    EXPECT_TRUE(latency.frameSwapped(3, 2, at(40)).empty()) << "an edit is measured once";
}

TEST(ScreenLatency, OneFrameShowsEveryEditUpToItsOwn) {
    ScreenLatency latency;
    latency.editApplied(1, "a", at(0), at(1));
    latency.editApplied(2, "b", at(5), at(6));
    latency.editApplied(4, "c", at(9), at(10));  // 3 was a display change: never applied here
    const std::vector<ScreenLatencyRecord> shown = latency.frameSwapped(2, 1, at(20));
    ASSERT_EQ(shown.size(), 2u);
    EXPECT_DOUBLE_EQ(shown[0].inputToSwapMillis(), 20.0);
    EXPECT_DOUBLE_EQ(shown[1].inputToSwapMillis(), 15.0);
    EXPECT_EQ(latency.pending(), 1u) << "edit 4 waits on";
    ASSERT_EQ(latency.frameSwapped(4, 1, at(30)).size(), 1u);
    // Median of 20, 15 and 21.
    EXPECT_DOUBLE_EQ(latency.recentMedianMillis(), 20.0);
}

TEST(ScreenLatency, InputLaterThanTheApplyCountsFromTheApply) {
    // An edit without input behind it (a playing timeline) has no earlier start than its apply.
    ScreenLatency latency;
    latency.editApplied(1, "Animate", at(50), at(40));
    const std::vector<ScreenLatencyRecord> shown = latency.frameSwapped(1, 1, at(45));
    ASSERT_EQ(shown.size(), 1u);
    EXPECT_DOUBLE_EQ(shown[0].inputToSwapMillis(), 5.0);
}

TEST(ScreenLatency, ForgetDropsTheEditsOfTheLastDocumentAndTheQueueIsBounded) {
    ScreenLatency latency;
    for (uint64_t e = 1; e <= ScreenLatency::kMaxPending + 10; ++e)
        latency.editApplied(e, "drag", at(0), at(0));
    EXPECT_EQ(latency.pending(), ScreenLatency::kMaxPending);
    const std::vector<ScreenLatencyRecord> shown = latency.frameSwapped(1000, 1, at(5));
    ASSERT_EQ(shown.size(), ScreenLatency::kMaxPending);
    EXPECT_EQ(shown.front().edit, 11u) << "the oldest were dropped";
    EXPECT_EQ(latency.recent().size(), ScreenLatency::kRecent);
    latency.editApplied(2000, "x", at(0), at(0));
    latency.forget();
    EXPECT_EQ(latency.pending(), 0u);
    EXPECT_TRUE(latency.frameSwapped(5000, 1, at(9)).empty());
}

TEST(ScreenLatency, LogLinesCarryTheTimesAsSteadyNanoseconds) {
    ScreenLatency latency;
    latency.editApplied(7, "Move \"glass\" sphere", at(0), at(3));
    const ScreenLatencyRecord r = latency.frameSwapped(7, 2, at(16)).at(0);
    const std::string line = latencyLogLine(r, "TLAS", "CUDA-GL interop (no host copy)", 16.5);
    EXPECT_NE(line.find("\"edit\":\"Move \\\"glass\\\" sphere\""), std::string::npos) << line;
    EXPECT_NE(line.find("\"swap_ns\":" + std::to_string(steadyNanoseconds(at(16)))), std::string::npos)
        << line;
    EXPECT_NE(line.find("\"input_ns\":" + std::to_string(steadyNanoseconds(at(0)))), std::string::npos)
        << line;
    EXPECT_NE(line.find("\"sync\":\"TLAS\""), std::string::npos) << line;
    EXPECT_NE(line.find("\"spp\":2"), std::string::npos) << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << "one line";
}

// The session's numbers: render edits count, display edits do not, and a sync takes the count.
TEST(ScreenLatency, TheSessionNumbersRenderEditsAndSyncsTakeTheNumber) {
    EditorSession session(createBackend("cpu"));
    session.adopt(test::ballUnderLampScene(16));
    session.sync();
    const uint64_t start = session.editSerial();
    EXPECT_EQ(session.syncedEdit(), start);
    Camera camera = session.document().scene.camera;
    camera.position.x += 0.1f;
    session.execute(setCamera(session.document(), camera));
    EXPECT_EQ(session.editSerial(), start + 1);
    EXPECT_EQ(session.syncedEdit(), start) << "not synced yet";
    ViewerSettings viewer = session.document().viewer;
    viewer.display.exposureStops = 1.0f;
    session.execute(setViewer(session.document(), viewer));
    EXPECT_EQ(session.editSerial(), start + 1) << "a display change is no edit to render";
    session.sync();
    EXPECT_EQ(session.syncedEdit(), start + 1);
    ASSERT_TRUE(session.undo());  // the exposure
    ASSERT_TRUE(session.undo());  // the camera
    EXPECT_EQ(session.editSerial(), start + 2);
    session.sync();
    EXPECT_EQ(session.syncedEdit(), start + 2);
}

}  // namespace
}  // namespace pt::editor
