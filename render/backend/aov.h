#pragma once
// The host side of AOVs (render/integrator/aov.h): names, and how a backend lays out, sizes and
// reads back the per-pixel sums. Both backends keep all enabled AOVs in one array of doubles:
// one plane per AOV (aovChannels() doubles per pixel), in the enum's order.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "render/integrator/aov.h"

namespace pt {

// "albedo", "shading_normal", "geometric_normal", "depth", "position", "uv", "roughness",
// "metallic", "emission", "instance_id", "material_id", "bvh_cost", "sample_count", "variance",
// "alpha".
const char* aovName(Aov a);
bool parseAov(const std::string& name, Aov& out);  // false for an unknown name

size_t aovDoublesPerPixel(AovMask mask);
// Where AOV `aov`'s plane starts in the array of `mask`'s AOVs, in doubles.
size_t aovPlaneOffset(AovMask mask, Aov aov, size_t pixels);
// A bound on the samples some path AOVs accumulate (Backend::setAovSampleCap): the denoiser's
// guides settle within a few hundred samples, and every pass that records them runs the generic
// AOV kernel instead of the scene's specialised one.
struct AovSampleCap {
    AovMask aovs = 0;      // path AOVs only (kPathAovs): variance follows the beauty
    uint32_t samples = 0;  // at least 1 where aovs is not 0

    bool covers(Aov a) const { return (aovs & aovBit(a)) != 0; }
};

// Each AOV's sample count, for the kernels that average the sums (the GPU denoiser).
struct AovSampleCounts {
    uint32_t of[kAovCount];

    PT_HD uint32_t operator[](Aov a) const { return of[uint32_t(a)]; }
};

// The AOVs a backend accumulates and the sample each started at: with the beauty (0) after a
// reset, or later where Backend::changeAovs added it; and the beauty's samples each left out
// while an AovSampleCap held it.
struct AovSet {
    AovMask mask = 0;
    std::array<uint32_t, kAovCount> firstSample{};
    std::array<uint32_t, kAovCount> skipped{};

    // The samples AOV `a` holds when the beauty holds `samplesPerPixel`.
    uint32_t samples(Aov a, uint32_t samplesPerPixel) const {
        return samplesPerPixel - firstSample[size_t(a)] - skipped[size_t(a)];
    }
    AovSampleCounts samplesAt(uint32_t samplesPerPixel) const;
    // The AOVs the next pass records at `samplesPerPixel`: all but those `cap` holds full.
    AovMask recording(const AovSampleCap& cap, uint32_t samplesPerPixel) const;
    // The samples until the first AOV that `cap` holds and that still records fills up (no
    // limit: UINT32_MAX): backends end a call's passes or waves there, so that it stops at its
    // cap exactly.
    uint32_t samplesUntilFull(const AovSampleCap& cap, uint32_t samplesPerPixel) const;
    // After a pass of `passes` samples that recorded only `recorded`: the others skipped them.
    void skip(AovMask recorded, uint32_t passes);
    // `mask` from the next pass on, at `samplesPerPixel`: the AOVs kept keep their first
    // sample and skips, new ones start at the next.
    AovSet changedTo(AovMask next, uint32_t samplesPerPixel) const;
};

// Throws std::invalid_argument where `cap` names an AOV that is not a path AOV (variance and
// sample_count follow the beauty) or caps at 0 samples.
void checkAovSampleCap(const AovSampleCap& cap);

// The kernels' view of an array of aovDoublesPerPixel(set.mask) x pixels doubles at `base`,
// recording only the AOVs in `recording` (AovSet::recording; each of set.mask has its plane).
AovBuffers aovBuffersIn(double* base, const AovSet& set, size_t pixels, AovMask recording = kAllAovs);

// The planes the AOVs in both `before` and `after` have in an array laid out for each, for
// carrying their sums over when the AOVs change (Backend::changeAovs): doubles from `from`
// in the old array go to `to` in the new.
struct AovPlaneMove {
    size_t from = 0, to = 0, doubles = 0;
};
std::vector<AovPlaneMove> keptAovPlanes(AovMask before, AovMask after, size_t pixels);

// Throws std::invalid_argument naming the AOV when it is not in `enabled`.
void requireAov(AovMask enabled, Aov aov);

// The value of channel c of one pixel's sums (aovChannels(aov) doubles at `sums`), as the
// image shows it: averages, except the ids (as stored), sample_count (`samples`) and the
// variance of the mean (Welford: M2 / (n - 1), over n). Sums are multiplied by 1 / n, not
// divided by n: a double division is a long sequence on the GPU, and inlined, the calls for
// one pixel's AOV share one 1 / n (the denoiser's guides went from twelve divisions a pixel to
// six, and its prepareKernel from 145 to 106 us at 1080p on the H200).
PT_HD float aovPixelValue(Aov aov, const double* sums, uint32_t c, uint32_t samples) {
    const double n = double(samples);
    switch (aov) {
        case Aov::SampleCount: return float(samples);
        case Aov::InstanceId:
        case Aov::MaterialId: return float(sums[0]);
        case Aov::Variance: return samples > 1 ? float(sums[1] * (1.0 / ((n - 1.0) * n))) : 0.0f;
        default: return samples ? float(sums[c] * (1.0 / n)) : 0.0f;
    }
}

// RGBA floats (A = 1) of AOV `aov` from its plane of sums over `samples` samples: averages,
// except the ids (as stored) and sample_count (`samples`). One-channel AOVs fill R, G and B.
// The variance is of the beauty's mean, over its `beautySamples` samples (the AOV's own
// `samples` estimate the spread of one sample: fewer where the AOV started later).
void aovImageFromSums(Aov aov, const double* plane, size_t pixels, uint32_t samples, uint32_t beautySamples,
                      std::vector<float>& rgba);

}  // namespace pt
