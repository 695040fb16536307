// Backend::readDenoised as every backend can run it (HostDenoiser), and HostDenoiser.
#include <stdexcept>
#include <string>

#include "render/backend/backend.h"
#include "render/backend/host_denoiser.h"
#include "render/util/stopwatch.h"

namespace pt {

namespace {

// Every sample of the beauty, or as many as the cap's: settled. Whether the cap still covers
// the guide does not matter: one it stopped and the user then views or exports goes on from
// there, and is no less settled.
bool guideComplete(const Backend& backend, Aov guide) {
    if (!(backend.aovs() & aovBit(guide))) return false;
    const uint32_t held = backend.aovSamples(guide);
    const AovSampleCap cap = backend.aovSampleCap();
    return held == backend.stats().samplesPerPixel || (cap.samples > 0 && held >= cap.samples);
}

}  // namespace

AovSampleCap settledGuideCap(AovMask kept, uint32_t samples) {
    return samples == 0 ? AovSampleCap{} : AovSampleCap{kDenoiseGuideAovs & kPathAovs & ~kept, samples};
}

bool denoiseGuidesComplete(const Backend& backend) {
    for (const Aov guide : kDenoiseGuides) {
        if (!guideComplete(backend, guide)) return false;
    }
    return true;
}

void requireDenoiseGuides(const Backend& backend) {
    const uint32_t samples = backend.stats().samplesPerPixel;
    for (const Aov guide : kDenoiseGuides) {
        requireAov(backend.aovs(), guide);
        if (!guideComplete(backend, guide)) {
            throw std::invalid_argument(std::string("denoiser guide \"") + aovName(guide) + "\" holds " +
                                        std::to_string(backend.aovSamples(guide)) + " of the beauty's " +
                                        std::to_string(samples) + " samples (reset the accumulation)");
        }
    }
}

double HostDenoiser::run(const Backend& backend, std::vector<float>& rgba) {
    requireDenoiseGuides(backend);
    backend.readBeauty(beauty_);
    backend.readAov(Aov::Albedo, albedo_);
    backend.readAov(Aov::ShadingNormal, normal_);
    backend.readAov(Aov::Depth, depth_);
    backend.readAov(Aov::Emission, emission_);
    backend.readAov(Aov::Alpha, alpha_);
    backend.readAov(Aov::Variance, variance_);
    DenoiseInput in;
    in.samples = backend.stats().samplesPerPixel;
    in.beauty = beauty_.data();
    in.varianceOfMean = variance_.data();
    in.guides = {backend.width(), backend.height(), albedo_.data(), normal_.data(),
                 depth_.data(),   emission_.data(), alpha_.data()};
    const auto start = Clock::now();
    filter_.run(in, rgba);
    return secondsSince(start);
}

double Backend::readDenoised(std::vector<float>& rgba) const { return HostDenoiser().run(*this, rgba); }

}  // namespace pt
