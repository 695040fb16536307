#include "render_test_support.h"

#include <cmath>

namespace pt::test {

double blockRelativeError(const std::vector<float>& image, const std::vector<float>& reference,
                          uint32_t width, uint32_t height, uint32_t block) {
    const uint32_t bw = width / block, bh = height / block;
    double sum = 0.0;
    for (uint32_t by = 0; by < bh; ++by) {
        for (uint32_t bx = 0; bx < bw; ++bx) {
            for (uint32_t c = 0; c < 3; ++c) {
                double x = 0.0, r = 0.0;
                for (uint32_t y = by * block; y < (by + 1) * block; ++y) {
                    for (uint32_t px = bx * block; px < (bx + 1) * block; ++px) {
                        const size_t i = (size_t(y) * width + px) * 4 + c;
                        x += image[i];
                        r += reference[i];
                    }
                }
                x /= block * block;
                r /= block * block;
                sum += std::fabs(x - r) / (r + 0.01);
            }
        }
    }
    return sum / (double(bw) * bh * 3);
}

}  // namespace pt::test
