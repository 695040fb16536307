#include "editor/screen_latency.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace pt::editor {

namespace {

double millisBetween(ScreenLatencyRecord::TimePoint from, ScreenLatencyRecord::TimePoint to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
}

}  // namespace

double ScreenLatencyRecord::inputToSwapMillis() const { return millisBetween(input, swapped); }
double ScreenLatencyRecord::inputToApplyMillis() const { return millisBetween(input, applied); }

void ScreenLatency::editApplied(uint64_t edit, std::string label, Clock::time_point input,
                                Clock::time_point applied) {
    ScreenLatencyRecord record;
    record.label = std::move(label);
    record.edit = edit;
    record.input = std::min(input, applied);  // an edit with no input behind it counts from its apply
    record.applied = applied;
    pending_.push_back(std::move(record));
    if (pending_.size() > kMaxPending) pending_.pop_front();
}

bool ScreenLatency::resolves(uint64_t frameEdit, uint32_t spp) const {
    // Pending edits are in the order applied, so the oldest is the first a frame can show.
    return spp > 0 && !pending_.empty() && pending_.front().edit <= frameEdit;
}

std::vector<ScreenLatencyRecord> ScreenLatency::frameSwapped(uint64_t frameEdit, uint32_t spp,
                                                             Clock::time_point swapped) {
    std::vector<ScreenLatencyRecord> shown;
    while (resolves(frameEdit, spp)) {
        ScreenLatencyRecord record = std::move(pending_.front());
        pending_.pop_front();
        record.swapped = swapped;
        record.samplesPerPixel = spp;
        recent_.push_back(record);
        if (recent_.size() > kRecent) recent_.pop_front();
        shown.push_back(std::move(record));
    }
    return shown;
}

double medianOf(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double ScreenLatency::recentMedianMillis() const {
    std::vector<double> millis;
    for (const ScreenLatencyRecord& r : recent_) millis.push_back(r.inputToSwapMillis());
    return medianOf(std::move(millis));
}

int64_t steadyNanoseconds(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
}

std::string latencyLogLine(const ScreenLatencyRecord& record, const std::string& syncAction,
                           const std::string& framePath, double uiFrameMillis) {
    const nlohmann::json line = {{"edit", record.label},
                                 {"serial", record.edit},
                                 {"input_ns", steadyNanoseconds(record.input)},
                                 {"applied_ns", steadyNanoseconds(record.applied)},
                                 {"swap_ns", steadyNanoseconds(record.swapped)},
                                 {"input_to_swap_ms", record.inputToSwapMillis()},
                                 {"input_to_apply_ms", record.inputToApplyMillis()},
                                 {"spp", record.samplesPerPixel},
                                 {"sync", syncAction},
                                 {"frame_path", framePath},
                                 {"ui_frame_ms", uiFrameMillis}};
    return line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);  // names may not be UTF-8
}

}  // namespace pt::editor
