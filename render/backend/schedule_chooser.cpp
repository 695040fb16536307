#include "render/backend/schedule_chooser.h"

#include <algorithm>

namespace pt {

void ScheduleChooser::setKey(uint64_t key, bool tryCompressedWalk) {
    if (key == key_) return;
    if (kept_.size() >= kKeptKeys) kept_.clear();
    kept_[key_] = trial_;
    const auto found = kept_.find(key);
    if (found != kept_.end()) {
        trial_ = found->second;
    } else {
        trial_ = Trial{};
        trial_.ways = tryCompressedWalk ? kWays : 2u;
    }
    key_ = key;
}

bool ScheduleChooser::decided() const {
    for (uint32_t w = 0; w < trial_.ways; ++w) {
        if (trial_.passes[w] < kTrialPassesEach) return false;
    }
    return true;
}

uint32_t ScheduleChooser::fastestWay(std::optional<bool> megakernel) const {
    uint32_t best = kWays;
    for (uint32_t w = 0; w < trial_.ways; ++w) {
        if (trial_.passes[w] == 0 || (megakernel && schedule(w).megakernel != *megakernel)) continue;
        if (best == kWays || trial_.seconds[w] < trial_.seconds[best]) best = w;
    }
    return best;
}

PassSchedule ScheduleChooser::next() const {
    if (decided()) return schedule(fastestWay());
    uint32_t fewest = 0;  // the way with the fewest passes, the first of equals
    for (uint32_t w = 1; w < trial_.ways; ++w) {
        if (trial_.passes[w] < trial_.passes[fewest]) fewest = w;
    }
    return schedule(fewest);
}

void ScheduleChooser::record(PassSchedule pass, double secondsPerSample) {
    const uint32_t w = way(pass);
    double& fastest = trial_.seconds[w];
    fastest = trial_.passes[w] == 0 ? secondsPerSample : std::min(fastest, secondsPerSample);
    ++trial_.passes[w];
}

double ScheduleChooser::fastestSeconds(bool megakernel) const {
    const uint32_t w = fastestWay(megakernel);
    return w < kWays ? trial_.seconds[w] : 0.0;
}

double ScheduleChooser::megakernelRate() const { return rate(fastestSeconds(true)); }
double ScheduleChooser::wavefrontRate() const { return rate(fastestSeconds(false)); }

std::string ScheduleChooser::choice() const {
    if (!decided()) return "measuring";
    return next().megakernel ? "megakernel" : "wavefront";
}

std::string ScheduleChooser::walkChoice() const {
    if (!decided() || trial_.ways != kWays) return "";
    return next().compressedWalk ? "compressed" : "binary";
}

}  // namespace pt
