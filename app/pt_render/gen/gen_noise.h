#pragma once
// The smooth, seeded displacement of generated spheres: a sum of plane waves
// a_i sin(k_i . p + phase_i) over three octaves, with random directions and phases. Chosen over
// lattice noise because it is smooth everywhere, has an exact gradient (so normals are the
// surface's, not finite differences), and is bounded: |value| <= 1 by construction, so a
// displacement of amplitude A keeps every point within 1 +- A of the centre.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "pt_render/gen/gen_random.h"

namespace pt::cli {

class WaveNoise {
public:
    static constexpr double kTwoPi = 6.283185307179586476925;

    explicit WaveNoise(uint64_t seed) {
        GenRandom random(seed ^ 0x6e6f697365ull);  // "noise": its own stream of the seed
        constexpr int kOctaves = 3, kWavesPerOctave = 4;
        double total = 0.0;
        for (int octave = 0; octave < kOctaves; ++octave) {
            const double frequency = 2.0 * double(1 << octave);
            const double amplitude = 1.0 / double(1 << octave);
            for (int i = 0; i < kWavesPerOctave; ++i) {
                // Uniform direction on the sphere (Archimedes: z uniform in [-1, 1]).
                const double z = random.uniform(-1.0, 1.0);
                const double phi = random.uniform(0.0, kTwoPi);
                const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
                waves_.push_back({frequency * s * std::cos(phi), frequency * s * std::sin(phi), frequency * z,
                                  random.uniform(0.0, kTwoPi), amplitude});
                total += amplitude;
            }
        }
        for (Wave& w : waves_) w.amplitude /= total;
    }

    // Value in [-1, 1] at p, and its gradient with respect to p.
    double evaluate(const double p[3], double gradient[3]) const {
        double value = 0.0;
        gradient[0] = gradient[1] = gradient[2] = 0.0;
        for (const Wave& w : waves_) {
            const double arg = w.k[0] * p[0] + w.k[1] * p[1] + w.k[2] * p[2] + w.phase;
            value += w.amplitude * std::sin(arg);
            const double slope = w.amplitude * std::cos(arg);
            for (int c = 0; c < 3; ++c) gradient[c] += slope * w.k[c];
        }
        return value;
    }

private:
    struct Wave {
        double k[3];
        double phase, amplitude;
    };
    std::vector<Wave> waves_;
};

}  // namespace pt::cli
