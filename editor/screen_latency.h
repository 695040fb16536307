#pragma once
// ScreenLatency: how long an edit takes to reach the screen, from the input event that made it
// to the swap of the first window frame that holds samples of it (issue 22). The render path's
// own figure (EditLatency: command to first pass) leaves out what a user waits for on either
// side: the frame the window was drawing when the event came, the queue while the render thread
// syncs, the frame's way to GL (interop or a host upload) and the swap. The window reports when
// input arrived, when each edit was applied and which edits each swapped frame shows; the Stats
// panel and `pathtracer --latency-log` read the records. No GL here, so it is tested without one.
#include <chrono>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace pt::editor {

struct ScreenLatencyRecord {
    using TimePoint = std::chrono::steady_clock::time_point;
    std::string label;  // the edit's, as the Stats panel names it ("Edit material glass")
    uint64_t edit = 0;  // EditorSession::editSerial() once it was applied
    TimePoint input, applied, swapped;
    uint32_t samplesPerPixel = 0;  // in the frame that showed it
    double inputToSwapMillis() const;
    double inputToApplyMillis() const;
};

class ScreenLatency {
public:
    using Clock = std::chrono::steady_clock;
    // Edits applied without a frame shown in between (a fast drag on a slow backend) wait here;
    // past this many the oldest are dropped (their frames come late anyway).
    static constexpr size_t kMaxPending = 256;
    static constexpr size_t kRecent = 32;  // records kept for the Stats panel's median

    // Edit `edit` (EditorSession::editSerial() after it) was applied at `applied` for input that
    // reached the window at `input`.
    void editApplied(uint64_t edit, std::string label, Clock::time_point input, Clock::time_point applied);
    // Whether swapping a frame that holds the edits up to `frameEdit` with `spp` samples ends a
    // wait: the window then finishes the swap (glFinish) before it reads the clock.
    bool resolves(uint64_t frameEdit, uint32_t spp) const;
    // That frame was swapped at `swapped`: the edits it shows leave the queue, measured.
    std::vector<ScreenLatencyRecord> frameSwapped(uint64_t frameEdit, uint32_t spp,
                                                  Clock::time_point swapped);
    // A new document: edits of the last one will never be shown.
    void forget() { pending_.clear(); }

    const std::deque<ScreenLatencyRecord>& recent() const { return recent_; }
    // Median input-to-swap time of the recent records; 0 with none.
    double recentMedianMillis() const;
    size_t pending() const { return pending_.size(); }

private:
    std::deque<ScreenLatencyRecord> pending_, recent_;
};

// One record as a line of JSON (`pathtracer --latency-log`): times as steady-clock nanoseconds
// (CLOCK_MONOTONIC on Linux, so a driver in another process can compare its own send times),
// with the sync action, how the frame reached the screen and the median UI frame time then.
std::string latencyLogLine(const ScreenLatencyRecord& record, const std::string& syncAction,
                           const std::string& framePath, double uiFrameMillis);
// The median of `values` (the mean of the middle two for an even count); 0 with none.
double medianOf(std::vector<double> values);
// Nanoseconds of a steady-clock time since the clock's epoch.
int64_t steadyNanoseconds(std::chrono::steady_clock::time_point t);

}  // namespace pt::editor
