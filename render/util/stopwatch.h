#pragma once
// Wall-clock seconds for the timings that stats, reports and benchmarks print.
#include <chrono>

namespace pt {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace pt
