#pragma once
// The checks a load and a compile run over every element of arrays of millions (a 10M-triangle
// mesh's 30M corner indices and its 30M position floats), in parallel: each reports the first
// bad element, as the serial loop it replaces did, so the error a user reads does not depend on
// the thread count.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstddef>

namespace pt {

// The lowest i in [0, count) for which fails(i) holds, or count where none does.
template <class Fails>
size_t firstFailing(size_t count, const Fails& fails) {
    constexpr size_t kGrain = size_t(1) << 16;
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, count, kGrain), count,
        [&](const tbb::blocked_range<size_t>& r, size_t found) {
            for (size_t i = r.begin(); i < r.end() && i < found; ++i) {
                if (fails(i)) return i;
            }
            return found;
        },
        [](size_t a, size_t b) { return std::min(a, b); });
}

}  // namespace pt
