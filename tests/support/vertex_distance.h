#pragma once
// How far two poses of one mesh's vertices lie apart.
#include <algorithm>
#include <vector>

#include "render/math/vec.h"

namespace pt::test {

// The largest distance between corresponding points (the arrays must be parallel).
inline float largestDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    float largest = 0.0f;
    for (size_t v = 0; v < std::min(a.size(), b.size()); ++v)
        largest = std::max(largest, length(a[v] - b[v]));
    return largest;
}

}  // namespace pt::test
