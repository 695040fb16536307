#pragma once
// The expectations of `pt-render stress`, as pure functions from measured images to an
// outcome (header-only, so tests can check that each one fails when it should). Every bound is
// the tolerance the case states plus what the measured noise allows: the images come from
// independent batches (batched_render.h), whose spread gives the variance of each pixel's mean.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "pt_render/batched_render.h"
#include "render/util/image_error.h"

namespace pt::cli {

struct StressOutcome {
    double error = 0.0;  // what was measured against the expectation
    double bound = 0.0;  // passes when error <= bound (and no sample was non-finite)
    uint64_t nonfiniteSamples = 0;
    std::string note;  // e.g. the loader's message, or why the case failed
    bool passed() const { return nonfiniteSamples == 0 && error <= bound && note.rfind("FAIL", 0) != 0; }
};

// Standard errors of a mean over this many sigmas count as noise, not as a failure.
constexpr double kNoiseSigmas = 4.0;

// `image` renders like `baseline`: relMSE between the two (each of independent seeds) at most
// `factor` times the relMSE their noise alone gives in expectation. A light leak, acne or a
// lost surface adds bias^2 that the noise does not explain.
inline StressOutcome matchesBaseline(const BatchedImage& image, const BatchedImage& baseline, double factor) {
    StressOutcome o;
    o.error = imageError(image.mean, baseline.mean).relMse;
    const double noise = noiseLevel(image.varianceOfMean, baseline.mean).relMse +
                         noiseLevel(baseline.varianceOfMean, baseline.mean).relMse;
    o.bound = factor * noise + 1e-12;  // two noise-free images must agree to rounding
    o.nonfiniteSamples = image.nonfiniteSamples + baseline.nonfiniteSamples;
    return o;
}

// Every channel's image mean lies in [lo, hi] to within `tolerance` (relative to hi) plus the
// noise of the mean. The error is the largest relative distance outside the range.
inline StressOutcome meanWithin(const BatchedImage& image, const std::array<double, 3>& lo,
                                const std::array<double, 3>& hi, double tolerance) {
    StressOutcome o;
    o.nonfiniteSamples = image.nonfiniteSamples;
    const std::vector<double> means = channelMeans(image.mean);
    const std::vector<double> variances = channelMeans(image.varianceOfMean);  // per pixel, averaged
    const double pixels = double(image.mean.size() / 4);
    double noise = 0.0;
    for (size_t c = 0; c < 3; ++c) {
        const double scale = std::max(hi[c], 1e-30);
        const double outside = std::max({lo[c] - means[c], means[c] - hi[c], 0.0}) / scale;
        o.error = std::max(o.error, std::isfinite(means[c]) ? outside : HUGE_VAL);
        // Pixels are independent, so the variance of the image mean is the mean variance / pixels.
        noise = std::max(noise, kNoiseSigmas * std::sqrt(variances[c] / pixels) / scale);
    }
    o.bound = tolerance + noise;
    char text[96];
    std::snprintf(text, sizeof text, "image mean %.6g, %.6g, %.6g", means[0], means[1], means[2]);
    o.note = text;
    return o;
}

inline StressOutcome meanEquals(const BatchedImage& image, const std::array<double, 3>& value,
                                double tolerance) {
    return meanWithin(image, value, value, tolerance);
}

// Loading must fail with one message naming every one of `needles` (the file, the element).
inline StressOutcome loadRefused(bool loaded, const std::string& message,
                                 const std::vector<std::string>& needles) {
    StressOutcome o;
    o.bound = 0.0;
    o.note = loaded ? "FAIL: loaded without an error" : message;
    for (const std::string& needle : needles) {
        if (!loaded && message.find(needle) == std::string::npos) {
            o.note = "FAIL: message lacks \"" + needle + "\": " + message;
            break;
        }
    }
    o.error = o.passed() ? 0.0 : 1.0;
    return o;
}

}  // namespace pt::cli
