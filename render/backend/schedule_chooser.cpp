#include "render/backend/schedule_chooser.h"

#include <algorithm>

namespace pt {

void ScheduleChooser::setKey(uint64_t key) {
    if (key == key_) return;
    *this = ScheduleChooser{};
    key_ = key;
}

bool ScheduleChooser::nextIsMegakernel() const {
    if (!decided()) return megakernelPasses_ <= wavefrontPasses_;
    return megakernelSeconds_ <= wavefrontSeconds_;
}

void ScheduleChooser::record(bool megakernel, double seconds) {
    uint32_t& passes = megakernel ? megakernelPasses_ : wavefrontPasses_;
    double& fastest = megakernel ? megakernelSeconds_ : wavefrontSeconds_;
    fastest = passes == 0 ? seconds : std::min(fastest, seconds);
    ++passes;
}

std::string ScheduleChooser::choice() const {
    if (!decided()) return "measuring";
    return nextIsMegakernel() ? "megakernel" : "wavefront";
}

}  // namespace pt
