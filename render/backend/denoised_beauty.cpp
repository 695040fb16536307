// Backend::readDenoised as every backend can run it: the guides read back, the CPU filter.
#include "render/backend/backend.h"
#include "render/denoise/denoiser.h"
#include "render/util/stopwatch.h"

namespace pt {

double Backend::readDenoised(std::vector<float>& rgba) const {
    for (const Aov guide : kDenoiseGuides) requireAov(aovs(), guide);
    std::vector<float> beauty, albedo, normal, depth, emission, alpha, variance;
    readBeauty(beauty);
    readAov(Aov::Albedo, albedo);
    readAov(Aov::ShadingNormal, normal);
    readAov(Aov::Depth, depth);
    readAov(Aov::Emission, emission);
    readAov(Aov::Alpha, alpha);
    readAov(Aov::Variance, variance);
    DenoiseInput in;
    in.samples = stats().samplesPerPixel;
    in.beauty = beauty.data();
    in.varianceOfMean = variance.data();
    in.guides = {width(),      height(),        albedo.data(), normal.data(),
                 depth.data(), emission.data(), alpha.data()};
    const auto start = Clock::now();
    denoiseOnCpu(in, rgba);
    return secondsSince(start);
}

}  // namespace pt
