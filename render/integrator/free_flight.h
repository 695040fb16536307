#pragma once
// Free-flight distance sampling in a homogeneous medium whose extinction differs per colour
// channel (skin scatters red farther than blue; issue 15). One channel's exponential is sampled,
// the channel picked in proportion to the path's throughput times the medium's single-scattering
// albedo, and the sample is weighted by the one-sample MIS density over all channels ("spectral
// MIS": Miller, Georgiev and Jarosz 2019, "A Null-Scattering Path Integral Formulation of Light
// Transport", sec. 5.1; Cycles' volume_sample_channel), so a coloured medium stays unbiased in
// every channel however far apart their extinctions are.
//
//   scatter at t < tMax:  weight = Tr(t) sigma_s / sum_c p_c sigma_t,c exp(-sigma_t,c t)
//   reach tMax:           weight = Tr(tMax) / sum_c p_c exp(-sigma_t,c tMax)
#include "render/math/vec.h"

namespace pt {

struct FreeFlight {
    bool scattered;  // a scattering event at `distance`; else the flight reached tMax
    float distance;
    Vec3 weight;  // multiplies the throughput (phase sampling's weight not included)
};

// The channel probabilities: throughput x albedo, normalised; uniform where that is black.
PT_HD Vec3 freeFlightChannelProbabilities(Vec3 sigmaT, Vec3 sigmaS, Vec3 throughput) {
    Vec3 p;
    for (int c = 0; c < 3; ++c) {
        const float albedo = sigmaT[c] > 0.0f ? sigmaS[c] / sigmaT[c] : 0.0f;
        p[c] = fmaxf(throughput[c] * albedo, 0.0f);
    }
    const float sum = p.x + p.y + p.z;
    return sum > 0.0f && isFinite(sum) ? p * (1.0f / sum) : Vec3(1.0f / 3.0f);
}

// tMax may be infinite (a medium with no surface ahead: the flight always scatters then, or
// the weight is zero where no channel can). uChannel and uDistance in [0, 1).
PT_HD FreeFlight sampleFreeFlight(Vec3 sigmaT, Vec3 sigmaS, Vec3 throughput, float tMax, float uChannel,
                                  float uDistance) {
    const Vec3 p = freeFlightChannelProbabilities(sigmaT, sigmaS, throughput);
    const int channel = uChannel < p.x ? 0 : uChannel < p.x + p.y ? 1 : 2;
    const float s = sigmaT[channel];
    // -log(1 - u) / s: infinite for a channel that does not attenuate.
    const float t = s > 0.0f ? -log1pf(-uDistance) / s : kInf;
    FreeFlight f{};
    f.scattered = t < tMax;
    f.distance = f.scattered ? t : tMax;
    Vec3 transmittance;
    for (int c = 0; c < 3; ++c) transmittance[c] = sigmaT[c] > 0.0f ? expf(-sigmaT[c] * f.distance) : 1.0f;
    float pdf = 0.0f;
    for (int c = 0; c < 3; ++c) pdf += p[c] * (f.scattered ? sigmaT[c] * transmittance[c] : transmittance[c]);
    if (!(pdf > 0.0f)) return f;  // weight 0
    f.weight = (f.scattered ? transmittance * sigmaS : transmittance) * (1.0f / pdf);
    return f;
}

}  // namespace pt
