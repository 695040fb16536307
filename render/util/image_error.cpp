#include "render/util/image_error.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pt {

namespace {

void checkSizes(const std::vector<float>& image, const std::vector<float>& reference) {
    if (image.size() != reference.size() || image.size() % 4 != 0) {
        throw std::invalid_argument("image error: " + std::to_string(image.size()) + " values against " +
                                    std::to_string(reference.size()) + " in the reference");
    }
}

// Calls f(x, r) for the R, G and B value of every pixel; returns how many there were.
template <class F>
size_t forEachColorValue(const std::vector<float>& image, const std::vector<float>& reference, F&& f) {
    for (size_t i = 0; i < image.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) f(double(image[i + c]), double(reference[i + c]));
    }
    return image.size() / 4 * 3;
}

}  // namespace

ImageError imageError(const std::vector<float>& image, const std::vector<float>& reference) {
    checkSizes(image, reference);
    double relSum = 0.0, squareSum = 0.0, percentSum = 0.0;
    const size_t n = forEachColorValue(image, reference, [&](double x, double r) {
        const double d = x - r;
        relSum += d * d / (r * r + kRelativeErrorEpsilon);
        squareSum += d * d;
        percentSum += std::fabs(d) / (std::fabs(r) + kRelativeErrorEpsilon);
    });
    if (n == 0) return {};
    return {relSum / double(n), std::sqrt(squareSum / double(n)), 100.0 * percentSum / double(n)};
}

NoiseLevel noiseLevel(const std::vector<float>& variance, const std::vector<float>& reference) {
    checkSizes(variance, reference);
    double relSum = 0.0, sum = 0.0;
    const size_t n = forEachColorValue(variance, reference, [&](double v, double r) {
        relSum += v / (r * r + kRelativeErrorEpsilon);
        sum += v;
    });
    if (n == 0) return {};
    return {relSum / double(n), std::sqrt(sum / double(n))};
}

std::vector<double> channelMeans(const std::vector<float>& image) {
    std::vector<double> means(3, 0.0);
    const size_t pixels = image.size() / 4;
    for (size_t i = 0; i < pixels; ++i) {
        for (size_t c = 0; c < 3; ++c) means[c] += image[i * 4 + c];
    }
    for (double& m : means) m = pixels ? m / double(pixels) : 0.0;
    return means;
}

bool allFinite(const std::vector<float>& image) {
    for (size_t i = 0; i < image.size(); ++i) {
        if (i % 4 != 3 && !std::isfinite(image[i])) return false;
    }
    return true;
}

}  // namespace pt
