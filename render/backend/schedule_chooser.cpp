#include "render/backend/schedule_chooser.h"

#include <algorithm>

namespace pt {

void ScheduleChooser::setKey(uint64_t key) {
    if (key == key_) return;
    if (kept_.size() >= kKeptKeys) kept_.clear();
    kept_[key_] = trial_;
    const auto found = kept_.find(key);
    trial_ = found != kept_.end() ? found->second : Trial{};
    key_ = key;
}

bool ScheduleChooser::nextIsMegakernel() const {
    if (!decided()) return trial_.megakernelPasses <= trial_.wavefrontPasses;
    return trial_.megakernelSeconds <= trial_.wavefrontSeconds;
}

void ScheduleChooser::record(bool megakernel, double secondsPerSample) {
    uint32_t& passes = megakernel ? trial_.megakernelPasses : trial_.wavefrontPasses;
    double& fastest = megakernel ? trial_.megakernelSeconds : trial_.wavefrontSeconds;
    fastest = passes == 0 ? secondsPerSample : std::min(fastest, secondsPerSample);
    ++passes;
}

std::string ScheduleChooser::choice() const {
    if (!decided()) return "measuring";
    return nextIsMegakernel() ? "megakernel" : "wavefront";
}

}  // namespace pt
