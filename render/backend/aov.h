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
// The AOVs a backend accumulates and the sample each started at: with the beauty (0) after a
// reset, or later where Backend::changeAovs added it.
struct AovSet {
    AovMask mask = 0;
    std::array<uint32_t, kAovCount> firstSample{};

    // The samples AOV `a` holds when the beauty holds `samplesPerPixel`.
    uint32_t samples(Aov a, uint32_t samplesPerPixel) const {
        return samplesPerPixel - firstSample[size_t(a)];
    }
    // `mask` from the next pass on, at `samplesPerPixel`: the AOVs kept keep their first
    // sample, new ones start at the next.
    AovSet changedTo(AovMask next, uint32_t samplesPerPixel) const;
};

// The kernels' view of an array of aovDoublesPerPixel(set.mask) x pixels doubles at `base`.
AovBuffers aovBuffersIn(double* base, const AovSet& set, size_t pixels);

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
// variance of the mean (Welford: M2 / (n - 1), over n).
PT_HD float aovPixelValue(Aov aov, const double* sums, uint32_t c, uint32_t samples) {
    const double n = double(samples);
    switch (aov) {
        case Aov::SampleCount: return float(samples);
        case Aov::InstanceId:
        case Aov::MaterialId: return float(sums[0]);
        case Aov::Variance: return samples > 1 ? float(sums[1] / ((n - 1.0) * n)) : 0.0f;
        default: return samples ? float(sums[c] / n) : 0.0f;
    }
}

// RGBA floats (A = 1) of AOV `aov` from its plane of sums over `samples` samples: averages,
// except the ids (as stored) and sample_count (`samples`). One-channel AOVs fill R, G and B.
// The variance is of the beauty's mean, over its `beautySamples` samples (the AOV's own
// `samples` estimate the spread of one sample: fewer where the AOV started later).
void aovImageFromSums(Aov aov, const double* plane, size_t pixels, uint32_t samples, uint32_t beautySamples,
                      std::vector<float>& rgba);

}  // namespace pt
