#pragma once
// Chi-square goodness of fit of a direction sampler against the density it claims, in the manner
// of pbrt-v4's chi2test and Mitsuba 3's ChiSquareTest: histogram the samples, integrate the pdf
// numerically over the same cells, pool cells expecting fewer than 5 samples, and compare the
// statistic with the chi-square distribution.
//
// The cells are (cos theta, phi) cells about the normal, 10 x 20 per hemisphere (so the horizon,
// where reflection and transmission densities jump, is a cell boundary), with bin edges warped
// to resolve the lobe: each coordinate goes through an asinh warp centred on the lobe's axis
// (the mirror direction on wo's side, the refracted direction on the other) with a width of the
// order of the lobe's (~alpha). Uniform bins cannot resolve a lobe of alpha = 0.0025 (all
// samples land in one cell, and no quadrature that does not know where the spike is can
// integrate it); with the warp the same 200 cells spread such a lobe over many cells, the
// integrands stay smooth, and broad (diffuse) parts still cover the whole hemisphere.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/math/vec.h"

namespace pt::test {

constexpr double kPiD = 3.14159265358979323846;

struct DVec3 {
    double x, y, z;
};
inline DVec3 operator+(DVec3 a, DVec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline DVec3 operator-(DVec3 a, DVec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline DVec3 operator*(DVec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(DVec3 a, DVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline DVec3 normalized(DVec3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }
inline DVec3 toDouble(Vec3 v) { return {v.x, v.y, v.z}; }
inline Vec3 toFloat(DVec3 v) { return {float(v.x), float(v.y), float(v.z)}; }

struct DFrame {
    DVec3 t, b, n;
    static DFrame fromNormal(DVec3 n) {
        const double sign = std::copysign(1.0, n.z);
        const double a = -1.0 / (sign + n.z), c = n.x * n.y * a;
        return {{1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x}, {c, sign + n.y * n.y * a, -n.y}, n};
    }
    DVec3 toLocal(DVec3 v) const { return {dot(v, t), dot(v, b), dot(v, n)}; }
    DVec3 toWorld(DVec3 v) const { return t * v.x + b * v.y + n * v.z; }
};

// Small PCG32 (O'Neill), so results do not depend on the standard library's distributions.
struct Pcg32 {
    uint64_t state = 0x853c49e6748fea9bULL, inc = 0xda3e39cb94b95bdbULL;
    explicit Pcg32(uint64_t seed) {
        state = 0;
        next();
        state += seed;
        next();
    }
    uint32_t next() {
        const uint64_t old = state;
        state = old * 6364136223846793005ULL + inc;
        const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        const uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    float uniform() { return float(next() >> 8) * (1.0f / 16777216.0f); }
};

// The p-value: the regularised upper incomplete gamma Q(dof / 2, chi2 / 2) (Numerical Recipes 6.2).
inline double chiSquarePValue(double chi2, int dof) {
    if (dof <= 0) return 1.0;
    if (!(chi2 >= 0.0)) return 0.0;
    const double a = 0.5 * dof, x = 0.5 * chi2;
    if (x <= 0.0) return 1.0;
    const double lg = std::lgamma(a);
    if (x < a + 1.0) {  // series for P
        double sum = 1.0 / a, term = sum;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
        }
        return std::max(0.0, 1.0 - sum * std::exp(-x + a * std::log(x) - lg));
    }
    double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;  // continued fraction for Q
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::fabs(c) < 1e-300) c = 1e-300;
        d = 1.0 / d;
        const double del = d * c;
        h *= del;
        if (std::fabs(del - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - lg) * h;
}

// Šidák-corrected per-test significance so that `tests` tests together reject a correct
// implementation with probability `familyLevel`.
inline double sidakLevel(double familyLevel, int tests) {
    return 1.0 - std::pow(1.0 - familyLevel, 1.0 / tests);
}

// t = (asinh((v - center) / width) - A) / (B - A) maps [lo, hi] onto [0, 1], densely near center.
struct AsinhWarp {
    double center = 0.0, width = 1.0, a = 0.0, b = 1.0;
    AsinhWarp() = default;
    AsinhWarp(double center_, double width_, double lo, double hi)
        : center(center_),
          width(width_),
          a(std::asinh((lo - center_) / width_)),
          b(std::asinh((hi - center_) / width_)) {}
    double toUnit(double v) const { return (std::asinh((v - center) / width) - a) / (b - a); }
    double fromUnit(double t, double& derivative) const {
        const double u = a + t * (b - a);
        derivative = width * std::cosh(u) * (b - a);
        return center + width * std::sinh(u);
    }
};

struct LobeHistogram {
    static constexpr int kThetaBins = 10, kPhiBins = 20, kSides = 2;
    static constexpr int kCells = kSides * kThetaBins * kPhiBins;
    AsinhWarp elevation[kSides];  // over x = 1 - |cos theta| in [0, 1]; [0]: wi.z >= 0, [1]: wi.z < 0
    AsinhWarp azimuth[kSides];    // over phi - phi0 in [-pi, pi]
    double phi0[kSides];

    // Each side's lobe axis and angular width (radians).
    LobeHistogram(DVec3 upperAxis, double upperWidth, DVec3 lowerAxis, double lowerWidth) {
        setSide(0, normalized(upperAxis), upperWidth);
        setSide(1, normalized(lowerAxis), lowerWidth);
    }
    void setSide(int side, DVec3 axis, double width) {
        const double sinTheta = std::sqrt(axis.x * axis.x + axis.y * axis.y);
        const double x0 = sinTheta * sinTheta / (1.0 + std::fabs(axis.z));
        elevation[side] = AsinhWarp(x0, width * sinTheta + 0.5 * width * width + 1e-9, 0.0, 1.0);
        // Sideways a lobe spans ~width |cos| radians of arc (reflection squashes it at grazing
        // angles), i.e. that over sin theta in azimuth.
        const double arc = width * std::max(std::fabs(axis.z), width);
        azimuth[side] = AsinhWarp(0.0, std::min(kPiD, arc / std::max(sinTheta, width)), -kPiD, kPiD);
        phi0[side] = std::atan2(axis.y, axis.x);
    }

    int cellOf(Vec3 wiFloat) const {
        const DVec3 w = normalized(toDouble(wiFloat));
        const int side = w.z >= 0.0 ? 0 : 1;
        const double x = (w.x * w.x + w.y * w.y) / (1.0 + std::fabs(w.z));  // 1 - |cos|, no cancellation
        double psi = std::atan2(w.y, w.x) - phi0[side];
        while (psi < -kPiD) psi += 2.0 * kPiD;
        while (psi >= kPiD) psi -= 2.0 * kPiD;
        const int ia = std::clamp(int(elevation[side].toUnit(x) * kThetaBins), 0, kThetaBins - 1);
        const int ib = std::clamp(int(azimuth[side].toUnit(psi) * kPhiBins), 0, kPhiBins - 1);
        return (side * kThetaBins + ia) * kPhiBins + ib;
    }

    // The direction at cell coordinates (t, s) in [0, 1]^2 of `side`, with the solid-angle
    // Jacobian d(omega) / (dt ds) = dx/dt dpsi/ds.
    DVec3 direction(int side, double t, double s, double& jacobian) const {
        double dxdt, dpsids;
        const double x = std::clamp(elevation[side].fromUnit(t, dxdt), 0.0, 1.0);
        const double phi = azimuth[side].fromUnit(s, dpsids) + phi0[side];
        const double cosTheta = 1.0 - x, sinTheta = std::sqrt(std::max(0.0, x * (2.0 - x)));
        jacobian = dxdt * dpsids;
        return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), side == 0 ? cosTheta : -cosTheta};
    }
};

struct ChiSquareResult {
    double pValue = 0.0;
    double chi2 = 0.0;
    int dof = 0;
    double pdfIntegral = 0.0;      // of the pdf over the sphere
    double sampledFraction = 0.0;  // valid non-delta samples / samples drawn
    std::string failure;           // non-empty when a sample fell where the pdf is zero
};

using DirectionSampler = std::function<bool(Pcg32&, Vec3&)>;  // false: no (non-delta) sample
using DirectionPdf = std::function<double(Vec3)>;

// Integral of f over [a0,a1] x [b0,b1]: 3 x 3 Gauss-Legendre, refined into quadrants until the
// quadrants agree with their parent to `tolerance` (halved per level; depth-limited), and at
// least minDepth times: a narrow lobe between the nodes of a coarse pass would otherwise read
// as none (an anisotropic glass lobe, alpha 0.0025 one way and 0.25 the other, did).
template <typename F>
double integrateAdaptive(const F& f, double a0, double a1, double b0, double b1, double whole,
                         double tolerance, int depth, int minDepth) {
    auto gauss = [&](double x0, double x1, double y0, double y1) {
        const double node[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
        const double weight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
        const double hx = 0.5 * (x1 - x0), hy = 0.5 * (y1 - y0);
        double s = 0.0;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                s += weight[i] * weight[j] * f(x0 + hx * (1.0 + node[i]), y0 + hy * (1.0 + node[j]));
            }
        }
        return s * hx * hy;
    };
    const double am = 0.5 * (a0 + a1), bm = 0.5 * (b0 + b1);
    const double q[4] = {gauss(a0, am, b0, bm), gauss(am, a1, b0, bm), gauss(a0, am, bm, b1),
                         gauss(am, a1, bm, b1)};
    const double sum = q[0] + q[1] + q[2] + q[3];
    if (depth <= 0 || (minDepth <= 0 && std::fabs(sum - whole) <= tolerance)) return sum;
    const double t = 0.5 * tolerance;
    const int d = depth - 1, m = minDepth - 1;
    return integrateAdaptive(f, a0, am, b0, bm, q[0], t, d, m) +
           integrateAdaptive(f, am, a1, b0, bm, q[1], t, d, m) +
           integrateAdaptive(f, a0, am, bm, b1, q[2], t, d, m) +
           integrateAdaptive(f, am, a1, bm, b1, q[3], t, d, m);
}

// Expected probability of each cell under `pdf`.
inline std::vector<double> integrateCells(const LobeHistogram& h, const DirectionPdf& pdf,
                                          double sampleCount) {
    std::vector<double> p(LobeHistogram::kCells, 0.0);
    for (int side = 0; side < LobeHistogram::kSides; ++side) {
        auto f = [&](double t, double u) {
            double jacobian;
            const DVec3 w = h.direction(side, t, u, jacobian);
            return pdf(toFloat(w)) * jacobian;
        };
        for (int ia = 0; ia < LobeHistogram::kThetaBins; ++ia) {
            for (int ib = 0; ib < LobeHistogram::kPhiBins; ++ib) {
                const double a0 = double(ia) / LobeHistogram::kThetaBins,
                             a1 = double(ia + 1) / LobeHistogram::kThetaBins;
                const double b0 = double(ib) / LobeHistogram::kPhiBins,
                             b1 = double(ib + 1) / LobeHistogram::kPhiBins;
                const double hx = 0.5 * (a1 - a0), hy = 0.5 * (b1 - b0);
                const double coarse = 4.0 * hx * hy * f(0.5 * (a0 + a1), 0.5 * (b0 + b1));
                // Accuracy that keeps the count error well under its Poisson deviation.
                const double expected = std::max(5.0, std::fabs(coarse) * sampleCount);
                const double tolerance = 0.05 * std::sqrt(expected) / sampleCount;
                p[(side * LobeHistogram::kThetaBins + ia) * LobeHistogram::kPhiBins + ib] =
                    integrateAdaptive(f, a0, a1, b0, b1, coarse, tolerance, 10, 2);
            }
        }
    }
    return p;
}

// Chi-square statistic of observed against expected counts, with pbrt-v4's pooling.
inline ChiSquareResult chiSquare(const std::vector<double>& observed, const std::vector<double>& expected,
                                 double sampleCount) {
    ChiSquareResult r;
    std::vector<int> order(observed.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
    double pooledObserved = 0.0, pooledExpected = 0.0;
    for (int i : order) {
        if (expected[i] <= 0.0 && observed[i] > sampleCount * 1e-5) {
            r.failure = "samples in cell " + std::to_string(i) + " where the pdf integrates to 0 (" +
                        std::to_string(observed[i]) + " samples)";
        }
        if (expected[i] < 5.0) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
        } else {
            const double d = observed[i] - expected[i];
            r.chi2 += d * d / expected[i];
            ++r.dof;
        }
    }
    if (pooledExpected > 0.0 || pooledObserved > 0.0) {
        const double d = pooledObserved - pooledExpected;
        r.chi2 += pooledExpected > 0.0 ? d * d / pooledExpected : 1e300;
        ++r.dof;
    }
    r.dof -= 1;
    r.pValue = chiSquarePValue(r.chi2, r.dof);
    return r;
}

// Draws `sampleCount` samples, histograms them, and tests them against `pdf` (or against
// `expectedPdf` where given: the negative controls pass a deliberately wrong density).
inline ChiSquareResult runChiSquare(const LobeHistogram& h, const DirectionSampler& sample,
                                    const DirectionPdf& pdf, int sampleCount, uint64_t seed) {
    std::vector<double> observed(LobeHistogram::kCells, 0.0);
    Pcg32 rng(seed);
    int valid = 0;
    for (int i = 0; i < sampleCount; ++i) {
        Vec3 wi;
        if (!sample(rng, wi)) continue;
        ++valid;
        observed[h.cellOf(wi)] += 1.0;
    }
    const std::vector<double> cellProbability = integrateCells(h, pdf, sampleCount);
    std::vector<double> expected(cellProbability.size());
    double integral = 0.0;
    for (size_t i = 0; i < expected.size(); ++i) {
        integral += cellProbability[i];
        expected[i] = cellProbability[i] * sampleCount;
    }
    ChiSquareResult r = chiSquare(observed, expected, sampleCount);
    r.pdfIntegral = integral;
    r.sampledFraction = double(valid) / sampleCount;
    return r;
}

}  // namespace pt::test
