#include "editor/ui/latency_log.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace pt::editor {

LatencyLog::LatencyLog(const std::string& path) {
    if (path.empty()) return;
    out_.open(path, std::ios::trunc);
    if (!out_) throw std::runtime_error("cannot write the latency log " + path);
}

void LatencyLog::write(const std::string& line) {
    if (!on()) return;
    out_ << line << '\n';
    out_.flush();
}

void LatencyLog::glContext(const std::string& backend, const std::string& renderer,
                           const std::string& version) {
    write(nlohmann::json{{"event", "gl"}, {"backend", backend}, {"renderer", renderer}, {"version", version}}
              .dump());
}

void LatencyLog::frameSwapped(uint64_t document, uint32_t spp, const std::string& framePath,
                              ScreenLatency::Clock::time_point at) {
    if (!waitsForFirstFrame(document, spp)) return;
    firstFrameOf_ = document;
    write(nlohmann::json{{"event", "first_frame"},
                         {"document", document},
                         {"spp", spp},
                         {"frame_path", framePath},
                         {"swap_ns", steadyNanoseconds(at)}}
              .dump());
}

void LatencyLog::edit(const ScreenLatencyRecord& record, const std::string& syncAction,
                      const std::string& framePath, double uiFrameMillis) {
    write(latencyLogLine(record, syncAction, framePath, uiFrameMillis));
}

}  // namespace pt::editor
