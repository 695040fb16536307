#pragma once
// The beauty image both backends hand out: per-pixel RGB sums of `samples` samples, in double,
// divided into mean radiance as RGBA floats (A = 1), row-major, top row first.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pt {

inline void meanImageFromSums(const double* sums, size_t pixels, uint32_t samples, std::vector<float>& rgba) {
    rgba.assign(pixels * 4, 0.0f);
    const double scale = samples ? 1.0 / samples : 0.0;
    for (size_t i = 0; i < pixels; ++i) {
        rgba[i * 4 + 0] = float(sums[i * 3 + 0] * scale);
        rgba[i * 4 + 1] = float(sums[i * 3 + 1] * scale);
        rgba[i * 4 + 2] = float(sums[i * 3 + 2] * scale);
        rgba[i * 4 + 3] = 1.0f;
    }
}

}  // namespace pt
