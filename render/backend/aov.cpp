#include "render/backend/aov.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace pt {

namespace {

constexpr const char* kAovNames[kAovCount] = {
    "albedo",      "shading_normal", "geometric_normal", "depth",    "position",
    "uv",          "roughness",      "metallic",         "emission", "instance_id",
    "material_id", "bvh_cost",       "sample_count",     "variance", "alpha"};

}  // namespace

const char* aovName(Aov a) { return uint32_t(a) < kAovCount ? kAovNames[uint32_t(a)] : "unknown"; }

bool parseAov(const std::string& name, Aov& out) {
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (name == kAovNames[i]) {
            out = Aov(i);
            return true;
        }
    }
    return false;
}

size_t aovDoublesPerPixel(AovMask mask) {
    size_t doubles = 0;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (mask & aovBit(Aov(i))) doubles += aovChannels(Aov(i));
    }
    return doubles;
}

size_t aovPlaneOffset(AovMask mask, Aov aov, size_t pixels) {
    return aovDoublesPerPixel(mask & (aovBit(aov) - 1u)) * pixels;
}

AovSampleCounts AovSet::samplesAt(uint32_t samplesPerPixel) const {
    AovSampleCounts counts{};
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (mask & aovBit(Aov(i))) counts.of[i] = samples(Aov(i), samplesPerPixel);
    }
    return counts;
}

AovMask AovSet::recording(const AovSampleCap& cap, uint32_t samplesPerPixel) const {
    AovMask full = 0;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (cap.covers(Aov(i)) && samples(Aov(i), samplesPerPixel) >= cap.samples) full |= aovBit(Aov(i));
    }
    return mask & ~full;
}

uint32_t AovSet::samplesUntilFull(const AovSampleCap& cap, uint32_t samplesPerPixel) const {
    uint32_t until = UINT32_MAX;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (!(mask & aovBit(Aov(i))) || !cap.covers(Aov(i))) continue;
        const uint32_t held = samples(Aov(i), samplesPerPixel);
        if (held < cap.samples) until = std::min(until, cap.samples - held);
    }
    return until;
}

void AovSet::skip(AovMask recorded, uint32_t passes) {
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if ((mask & ~recorded) & aovBit(Aov(i))) skipped[i] += passes;
    }
}

AovSet AovSet::changedTo(AovMask next, uint32_t samplesPerPixel) const {
    AovSet changed;
    changed.mask = next;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        const AovMask bit = aovBit(Aov(i));
        if (!(next & bit)) continue;
        const bool kept = (mask & bit) != 0;
        changed.firstSample[i] = kept ? firstSample[i] : samplesPerPixel;
        changed.skipped[i] = kept ? skipped[i] : 0;
    }
    return changed;
}

void checkAovSampleCap(const AovSampleCap& cap) {
    const AovMask notPath = cap.aovs & ~kPathAovs;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (notPath & aovBit(Aov(i))) {
            throw std::invalid_argument(std::string("AOV \"") + aovName(Aov(i)) +
                                        "\" follows the beauty's samples and cannot be capped");
        }
    }
    if (cap.aovs != 0 && cap.samples == 0)
        throw std::invalid_argument("an AOV sample cap must be at least 1");
}

AovBuffers aovBuffersIn(double* base, const AovSet& set, size_t pixels, AovMask recording) {
    AovBuffers b{};
    b.mask = set.mask & recording;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        const Aov a = Aov(i);
        b.firstSample[i] = set.firstSample[i];
        if ((set.mask & aovBit(a)) && aovChannels(a) > 0)
            b.sums[i] = base + aovPlaneOffset(set.mask, a, pixels);
    }
    return b;
}

std::vector<AovPlaneMove> keptAovPlanes(AovMask before, AovMask after, size_t pixels) {
    std::vector<AovPlaneMove> moves;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        const Aov a = Aov(i);
        if ((before & after & aovBit(a)) && aovChannels(a) > 0) {
            moves.push_back({aovPlaneOffset(before, a, pixels), aovPlaneOffset(after, a, pixels),
                             aovChannels(a) * pixels});
        }
    }
    return moves;
}

void requireAov(AovMask enabled, Aov aov) {
    if (uint32_t(aov) >= kAovCount) throw std::invalid_argument("no such AOV");
    if (!(enabled & aovBit(aov))) {
        throw std::invalid_argument(std::string("AOV \"") + aovName(aov) +
                                    "\" is not enabled (setAovs, then reset the accumulation)");
    }
}

void aovImageFromSums(Aov aov, const double* plane, size_t pixels, uint32_t samples, uint32_t beautySamples,
                      std::vector<float>& rgba) {
    const uint32_t channels = aovChannels(aov);
    // The variance of the mean of the AOV's samples, to that of the beauty's.
    const float ofBeauty =
        aov == Aov::Variance && beautySamples > 0 ? float(samples) / float(beautySamples) : 1.0f;
    rgba.assign(pixels * 4, 0.0f);
    for (size_t i = 0; i < pixels; ++i) {
        const double* sums = plane ? plane + i * channels : nullptr;
        float* out = &rgba[i * 4];
        if (channels == 1 || aov == Aov::SampleCount || aov == Aov::Variance) {
            out[0] = out[1] = out[2] = aovPixelValue(aov, sums, 0, samples) * ofBeauty;
        } else {
            for (uint32_t c = 0; c < channels; ++c) out[c] = aovPixelValue(aov, sums, c, samples);
        }
        out[3] = 1.0f;
    }
}

}  // namespace pt
