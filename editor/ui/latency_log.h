#pragma once
// `pathtracer --latency-log FILE`: what ScreenLatency measured, as JSON lines for a driver
// program (tests/editor/latency: scripted input under Xvfb, on the CPU or the CUDA backend).
// Lines, each an object: {"event": "gl", ...} once (the GL renderer, so a run says whether the
// window drew on the GPU or in software), {"event": "first_frame", ...} at each document's first
// frame with samples on screen, then one line per edit shown (latencyLogLine). Each line is
// flushed as written: a driver reads the file while the editor runs.
#include <cstdint>
#include <fstream>
#include <string>

#include "editor/screen_latency.h"

namespace pt::editor {

class LatencyLog {
public:
    // "" writes nothing; a file that cannot be opened throws std::runtime_error naming it.
    explicit LatencyLog(const std::string& path);
    bool on() const { return out_.is_open(); }

    void glContext(const std::string& backend, const std::string& renderer, const std::string& version);
    // Whether a frame of `document` with `spp` samples would be that document's first.
    bool waitsForFirstFrame(uint64_t document, uint32_t spp) const {
        return on() && spp > 0 && document != firstFrameOf_;
    }
    // A frame of `document` with samples was swapped: the first of each document is written.
    void frameSwapped(uint64_t document, uint32_t spp, const std::string& framePath,
                      ScreenLatency::Clock::time_point at);
    void edit(const ScreenLatencyRecord& record, const std::string& syncAction, const std::string& framePath,
              double uiFrameMillis);

private:
    void write(const std::string& line);
    std::ofstream out_;
    uint64_t firstFrameOf_ = 0;  // the last document whose first frame was written
};

}  // namespace pt::editor
