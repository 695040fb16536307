#pragma once
// The per-pixel steps of the denoiser, shared by the CPU driver (denoiser.h) and the CUDA
// kernels (the CPU runs them a row of pixels at a time: row_filter.h): the spatial filter of
// SVGF (Schied et al. 2017, "Spatiotemporal Variance-Guided Filtering"), an edge-avoiding
// a-trous wavelet filter (Dammertz et al. 2010, "Edge-Avoiding A-Trous Wavelet Transform for
// fast Global Illumination Filtering") whose luminance edge stop is scaled by the estimated
// standard deviation of each pixel's mean. Why this method: it needs nothing but the guides the
// renderer already writes (first-hit albedo, shading normal, depth, the variance of the mean),
// it is five passes of 25 taps (at 512x512 about 16 ms a pass on one CPU core, as SIMD rows:
// row_filter.h; at 1080p 0.15 ms on an H100), and its luminance edge stop makes it fade out by
// itself: as samples grow the variance of the mean falls, the stop tightens, and a converged
// image passes through almost untouched. A feature regression (Koskela et al. 2019, BMFR)
// cleans more at 1 spp but blocks of least squares cost far more and need a temporal pass to
// hide their seams; we have no motion vectors to feed one.
//
// The filter works on demodulated radiance (radiance over albedo), so textures are multiplied
// back after filtering and keep their detail; the variance carried along is that of each
// pixel's mean luminance, filtered with the squared weights (SVGF, eq. 4).
// Images are row-major RGBA floats (what Backend::readBeauty and readAov return).
//
// Sections: the guides and the edge-stop constants; demodulation (demodulator,
// coverageFreeVariance, fewSamplesVariance, demodulatedSample, boundedByNoise, remodulated);
// the surface each pixel's edge stops compare (surfaceOf, depthSlopeAt, EdgeStops); the
// neighbours' variance estimate of the first samples (spatialVarianceAt) and their fireflies
// (fireflyLimit, inFireflyWindow, fireflyLimitAt, withoutFirefly); outliers
// (outlierWeight, neighbourhoodVarianceAt); one a-trous pass (atrousTapWeight, atrousAt).
#include <cstddef>
#include <cstdint>

#include "render/denoise/denoise_planes.h"
#include "render/math/half_float.h"  // bitsFloat
#include "render/math/hd.h"
#include "render/math/vec.h"

namespace pt {

// The guides, row-major RGBA averages over each pixel's samples: first-hit albedo, shading
// normal (xyz; 0 where the camera ray left the scene), depth (r; 0 where it left the scene),
// emission seen first (a light's face, or the environment where the camera ray left the
// scene), alpha (r: the fraction of samples that found a surface).
struct DenoiseGuides {
    uint32_t width, height;
    const float* albedo;
    const float* normal;
    const float* depth;
    const float* emission;
    const float* alpha;
};

namespace denoise {

// Edge-stopping strengths of SVGF (Schied et al. 2017, section 4.3): normals, depth and
// luminance as there. But our guides are averages over each pixel's antialiased samples: a
// crease pixel holds a mix of normals (their average is shorter than 1), and at power 128 it
// is cut off from every neighbour and keeps all its noise. So the power falls with the
// pixel's spread of normals, 1 - |average| / alpha (alpha: the part of the pixel on a
// surface): 128 for a pixel on one smooth surface (which keeps normal-mapped detail), about 6
// for one astride a right-angled crease. A silhouette pixel keeps its power: the sky beside
// it is not a spread of normals, and the rim of a ball is often truly darker than its face.
// Measured with the CPU backend, relMSE against 16384 spp, denoised over raw at 4 / 16 spp,
// Cornell box 128x128 and GolfBall 160x120: tolerance 256: 0.064 / 0.098 and 0.270 / 0.503;
// 64: 0.067 / 0.101 and 0.276 / 0.433; 32: 0.070 / 0.104 and 0.280 / 0.421. (Before alpha
// split the silhouette off, GolfBall at 16 spp was 0.80, with the rim 8x its raw error.)
constexpr float kNormalPower = 128.0f;
constexpr float kNormalSpreadTolerance = 64.0f;
constexpr float kDepthSigma = 1.0f;
// Luminance: 2 deviations, not SVGF's 4: with 4 the rim of GolfBall (dark grazing facets
// against the sky, noisy pixels whose neighbours truly differ) was smoothed into its
// neighbours, leaving 2.2x the raw relMSE at 16 spp; with 2, 0.81x (the Cornell box at 48x48,
// 4 spp: 8.0x less error with 4, 6.0x with 2).
constexpr float kLuminanceSigma = 2.0f;
// Albedo channels are divided out as no less than this (black or missing surfaces, whose
// radiance is not the albedo's to scale). Below it a channel is no longer demodulated, and
// takes in its neighbours' values of that channel unscaled: with a floor of 0.01, stripes of
// blue albedo 0.005 beside 0.03 came out 1.5x as blue as they are (the test
// Denoiser.AlbedoChannelsNearZeroKeepTheirScale); at 0.001 a black
// surface's demodulated radiance reaches half's largest value, 65504, at radiance 65 (past it,
// filteredRadiance gives the pixel its own excess back).
constexpr float kMinAlbedo = 0.001f;
// The a-trous filter's 1D B3-spline weights (Dammertz et al. 2010), for taps -2 .. 2.
PT_HD float splineWeight(int tap) {
    const int distance = tap < 0 ? -tap : tap;
    return distance == 0 ? 3.0f / 8.0f : (distance == 1 ? 1.0f / 4.0f : 1.0f / 16.0f);
}

PT_HD Vec3 loadRgb(const float* rgba, uint32_t i) { return {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]}; }

PT_HD float sanitized(float v) { return isFinite(v) ? v : 0.0f; }

// One pixel's guides (DenoiseGuides at pixel i); the GPU makes them from the sums directly.
struct PixelGuides {
    Vec3 albedo, normal, emission;
    float depth, alpha;
};

PT_HD PixelGuides guidesAt(const DenoiseGuides& g, uint32_t i) {
    return {loadRgb(g.albedo, i), loadRgb(g.normal, i), loadRgb(g.emission, i), g.depth[4 * i],
            g.alpha[4 * i]};
}

// What pixel i's reflected radiance is divided by, and multiplied back with: its albedo. The
// guides are averages over the pixel's samples, and samples that left the scene add 0 to the
// albedo and their sky to the emission guide, which is taken out before the division: what is
// left of a pixel half on a surface and half on the sky is the surface's half, divided by the
// surface's halved albedo. Channels of albedo below kMinAlbedo are divided by kMinAlbedo: the
// divisor must not jump where the albedo crosses it. It was 1 below it, so a pixel whose blue
// albedo was 0.007 beside one at 0.011 took in that neighbour's blue divided by 0.011 and
// multiplied it by 1, 143x too bright: on DepthOfFieldExample's green ground (blue albedo near
// 0.01; 160x120, CPU backend, against 8192 spp, the mean over four seeds) the denoised image had
// 31.6x the raw relMSE at 16 spp and 4.4x at 4, and has 0.46x and 0.63x with the divisor
// continuous (before the outlier weight below).
PT_HD Vec3 demodulator(Vec3 a) { return vmax(a, Vec3(kMinAlbedo)); }  // a NaN channel: kMinAlbedo

// The variance of a pixel's mean luminance (the variance AOV's value, over `samples` samples)
// without the noise of which of surface and sky each sample found. At a silhouette that is
// most of the variance, and demodulation takes it out exactly (the albedo and emission guides
// come from the same samples): left in, it loosened the rim's luminance stop and noise bound,
// and GolfBall's rim pixels (640x480, H100) ended at 1.3x their raw relMSE at 16 spp and 2.6x
// at 64 while the rest of the ball was at 0.18x and 0.38x. By the law of total variance over
// the pixel's own samples, with a the fraction on a surface:
//   M2 / n = a Var(surface) + (1 - a) Var(sky) + a (1 - a) (surface mean - sky mean)^2,
// so leaving Var(sky) >= 0 out bounds Var(surface) from above; the pixel's mean holds a times
// the mean of its a n surface samples. `surfaceLight`, `skyLight`: the luminances of what the
// two kinds add to the pixel's mean (beauty less the emission guide, and the emission guide).
// A pixel that is all sky (alpha 0) has none left: what it filters, beauty less emission, is 0.
// Left in, its sky's variance, divided by the albedo floor squared, reached the luminance stops
// of the surfaces beside it through the 3x3 blur (GolfBall under venice_sunset_1k.hdr, 160x120,
// CPU, four seeds against 4096 spp, 16 spp: 0.264 of the raw relMSE with it, 0.243 without, the
// rim's pixels 1.02 and 0.77; the filter before the albedo floor: 0.254 and 0.83).
PT_HD float coverageFreeVariance(float varianceOfMean, float alpha, float surfaceLight, float skyLight,
                                 uint32_t samples) {
    if (!(alpha > 0.0f)) return 0.0f;  // all sky: demodulatedSample takes out all of it, exactly
    const float hits = alpha * float(samples);
    if (!(alpha < 1.0f) || !(hits >= 2.0f)) return varianceOfMean;  // nothing to take out
    const float gap = surfaceLight / alpha - skyLight / (1.0f - alpha);
    const float surfaceSpread = varianceOfMean * float(samples - 1) - alpha * (1.0f - alpha) * gap * gap;
    return maxf(surfaceSpread, 0.0f) * alpha / (hits - 1.0f);
}

// A variance of the mean estimated from few samples, raised to the variance it stands for:
// a pixel's first samples are heavy-tailed (the rare path that finds a light adds far more than
// the typical one), and the spread of a few of them, or of a window of 1-sample neighbours
// (spatialVarianceAt), is the typical one. Left low, the luminance stop and the noise bound
// keep every pixel's outliers. SVGF's own implementation (Schied et al. 2017; Falcor's
// SVGFFilterMoments) multiplies its neighbours' estimate by 4 / samples for this; here both
// estimates are multiplied by 16 / samples below 16 samples, which paid on both test scenes
// (CPU backend, denoised over raw relMSE against 8192 / 4096 spp; Cornell box 128x128, GolfBall
// 160x120):
//   spp                      1      2      3      4      8      (16: unchanged)
//   none         Cornell   0.458  0.683  0.763  0.068  0.077
//                GolfBall  0.327  0.414  0.491  0.281  0.295
//   4 / spp      Cornell   0.062  0.170  0.289
//                GolfBall  0.197  0.216  0.261
//   16 / spp     Cornell   0.025  0.029  0.046  0.048  0.062
//                GolfBall  0.151  0.151  0.184  0.222  0.276
//   32 / spp     Cornell   0.024  0.026  0.037  0.044  0.054  (0.082 at 16)
//                GolfBall  0.140  0.138  0.172  0.212  0.276  (0.404 at 16: worse)
constexpr float kFewSamplesVarianceBoost = 16.0f;
PT_HD float fewSamplesVariance(float variance, uint32_t samples) {
    const float boost = kFewSamplesVarianceBoost / float(samples > 0 ? samples : 1);
    return boost > 1.0f && variance >= 0.0f ? variance * boost : variance;  // kInvalid stays
}

// A pixel's demodulated radiance and the variance of its mean luminance; a pixel with
// non-finite radiance is left out (kInvalid), so that it never spreads. Emission seen first
// (a light's face, the sky) is taken out before and put back after: it is not lit by anything,
// and a pixel half on a lamp would otherwise divide the lamp by the albedo of what is beside it.
// `radiance` and `varianceOfMean`: the pixel's mean beauty over `samples` samples and the
// variance AOV's value.
PT_HD DenoiseSample demodulatedSample(Vec3 radiance, float varianceOfMean, uint32_t samples,
                                      const PixelGuides& g) {
    const Vec3 emission = g.emission;
    if (!isFinite(radiance) || !isFinite(emission)) return {Vec3(0.0f), kInvalid};
    const Vec3 d = demodulator(g.albedo);
    const float variance = coverageFreeVariance(maxf(sanitized(varianceOfMean), 0.0f), sanitized(g.alpha),
                                                luminance(radiance - emission), luminance(emission), samples);
    const float scale = luminance(d);
    return {(radiance - emission) / d, fewSamplesVariance(variance / (scale * scale), samples)};
}

// The filtered value held within a few standard deviations of the pixel's own mean (in
// luminance, the move scaled down as a whole): the filter may take out what the noise can
// explain, and no more. This is what makes it fade out: the bound is kNoiseBound deviations
// up to kFullStrengthSamples samples a pixel and narrows as 1/samples past them, faster than
// the noise falls, because the bias the edge stops let through does not fall with it (at 4096
// spp on GolfBall the unbounded filter left 150x the raw relMSE, smoothing the shading of
// dimples under a normal map that the guides hardly see). A pixel whose variance is
// underestimated (a highlight every sample found) keeps its raw value.
constexpr float kNoiseBound = 3.0f;
constexpr float kFullStrengthSamples = 64.0f;
PT_HD Vec3 boundedByNoise(const DenoiseSample& input, Vec3 filtered, uint32_t samples) {
    if (!input.valid()) return filtered;  // nothing of its own to stay near: its neighbours' mean
    const float move = fabsf(luminance(filtered) - luminance(input.radiance));
    const float strength = minf(1.0f, kFullStrengthSamples / float(samples > 0 ? samples : 1));
    const float bound = kNoiseBound * strength * sqrtf(input.variance);
    return move > bound ? input.radiance + (filtered - input.radiance) * (bound / move) : filtered;
}

PT_HD Vec3 remodulated(Vec3 radiance, Vec3 albedo, Vec3 emission) {
    return radiance * demodulator(albedo) + (isFinite(emission) ? emission : Vec3(0.0f));
}

// The mean depth of the samples of a pixel that found a surface; 0 where none did. The depth
// guide averages 0 in for samples that left the scene, which would put a pixel half on an
// object at half its distance.
PT_HD float surfaceDepth(const PixelGuides& g) {
    return g.depth > 0.0f && g.alpha > 0.0f && isFinite(g.depth / g.alpha) ? g.depth / g.alpha : 0.0f;
}

// The depth slope, a pixel, between depths z0 and z1 `pixels` apart around a centre at zc: a
// central difference where both sides are on a surface, one-sided where one is (0: background,
// whose depth would read as a cliff and switch the depth stop off along every silhouette).
PT_HD float depthSlope(float z0, float zc, float z1, float pixels) {
    if (z0 > 0.0f && z1 > 0.0f) return fabsf(z1 - z0) / pixels;
    if (z0 > 0.0f || z1 > 0.0f) return fabsf((z0 > 0.0f ? z0 : z1) - zc) * (2.0f / pixels);
    return 0.0f;
}

// The larger of pixel (x, y)'s depth slopes along x and y, from its neighbours' surfaces.
PT_HD float depthSlopeAt(const DenoiseSurface* surfaces, uint32_t width, uint32_t height, uint32_t x,
                         uint32_t y) {
    const auto z = [&](uint32_t xx, uint32_t yy) { return surfaces[yy * width + xx].depth; };
    const uint32_t x0 = x > 0 ? x - 1 : x, x1 = x + 1 < width ? x + 1 : x;
    const uint32_t y0 = y > 0 ? y - 1 : y, y1 = y + 1 < height ? y + 1 : y;
    const float zc = z(x, y);
    const float dx = x1 > x0 ? depthSlope(z(x0, y), zc, z(x1, y), float(x1 - x0)) : 0.0f;
    const float dy = y1 > y0 ? depthSlope(z(x, y0), zc, z(x, y1), float(y1 - y0)) : 0.0f;
    return maxf(dx, dy);
}

// A pixel's surface, and in `normalPower` its own normal stop's power (its depth slope needs
// its neighbours' surfaces: depthSlopeAt).
PT_HD DenoiseSurface surfaceOf(const PixelGuides& g, float& normalPower) {
    const Vec3 n = g.normal;
    const float length = sqrtf(sanitized(dot(n, n))), alpha = sanitized(g.alpha);
    // Unit normals averaged over the samples that found a surface: shorter than 1 where the
    // pixel mixes surfaces (not where some of its samples found none).
    const float spread = alpha > 0.0f ? 1.0f - minf(length / alpha, 1.0f) : 0.0f;
    normalPower = kNormalPower / (1.0f + kNormalSpreadTolerance * spread);
    return {length > 0.0f && isFinite(n) ? n / length : Vec3(0.0f), surfaceDepth(g)};
}

constexpr float kDisjoint = -1e30f;  // the log weight of surfaces that share nothing

// e^x for x <= 0 as 2^(x log2 e), an a-trous tap's largest cost. On the GPU a multiply and the
// ex2 instruction, where expf adds a range reduction for accuracy that the weights do not
// need. On the host exp2f is a call into libm; there 2^x is 2^n times a degree-5 Taylor
// polynomial of 2^f, with n the nearest integer and |f| <= 1/2 (relative error below 1e-5),
// and 0 below 2^-126 (a denormal weight is none).
PT_HD float fastExp(float x) {
#if defined(__CUDA_ARCH__)
    // ex2's flush-to-zero form: one MUFU.EX2, where exp2f's keeps denormals with a scale on
    // either side; like the host's, a weight below 2^-126 is 0.
    float y;
    asm("ex2.approx.ftz.f32 %0, %1;" : "=f"(y) : "f"(x * 1.44269504f));
    return y;
#else
    const float t = x * 1.44269504f;
    if (!(t > -126.0f)) return 0.0f;
    const float rounder = 12582912.0f;  // 1.5 * 2^23: adding it rounds to an integer
    const float n = minf((t + rounder) - rounder, 127.0f), f = t - n;
    const float twoToF =
        1.0f + f * (0.693147182f +
                    f * (0.240226507f + f * (0.0555041087f + f * (0.00961812911f + f * 0.00133335581f))));
    return twoToF * bitsFloat(uint32_t(int32_t(n) + 127) << 23);
#endif
}

// How much a neighbour shares a centre pixel's surface, from the normals and depths (SVGF
// eq. 5, as one exponent). The normal stop is a spherical Gaussian, exp(power (cos - 1))
// (Wang et al. 2009, "All-Frequency Rendering of Dynamic, Spatially-Varying Reflectance"), not
// SVGF's cos^power: the two agree where the weight matters, near cos = 1, and the Gaussian
// needs no logarithm a tap (the same relMSE on the Cornell box and GolfBall at 4, 16 and 256
// spp to 2%). It uses the centre's power only; the smaller of the two powers changed nothing
// measurable either.
struct EdgeStops {
    DenoiseSurface center;
    SurfaceStops stops;

    // 1 / the depth difference that counts as one deviation `pixels` from the centre: its
    // depth slope times the distance, with room for the depth guide's rounding.
    PT_HD float inverseDepthScale(float pixels) const {
        return 1.0f / (kDepthSigma * stops.depthSlope * pixels + 1e-3f * center.depth);
    }
    // The log weight of q, `inverseDepthScale` away (taps at equal distances share one): the
    // background shares only with itself. Selects, not branches: a tap's cost is its
    // instructions (the GPU pass is issue-bound), and the CPU's row loops vectorise only where
    // the conditions are bitwise (&&'s short circuit left GCC a branch it would not convert).
    PT_HD float logWeight(const DenoiseSurface& q, float inverseDepth) const {
        const bool background = center.depth == 0.0f, missQ = q.depth == 0.0f;
        const float cosine = dot(center.normal, q.normal);
        const float shared =
            background ? 0.0f
                       : -fabsf(center.depth - q.depth) * inverseDepth + stops.normalPower * (cosine - 1.0f);
        return (background == missQ) & (background | (cosine > 0.0f)) ? shared : kDisjoint;
    }
};

// What spatialVarianceAt adds up for one pixel: its neighbours' luminances, weighted.
struct SpreadSums {
    float weight = 0.0f, luminance = 0.0f, squares = 0.0f;

    PT_HD void add(float w, float l) {
        weight += w;
        luminance += w * l;
        squares += w * l * l;
    }
    PT_HD float variance() const {  // weight >= 1: the pixel itself
        const float mean = luminance / weight;
        return maxf(squares / weight - mean * mean, 0.0f);
    }
};

// The weight in spatialVarianceAt of a neighbour q `distance` pixels from the centre (whose
// own weight is 1): its surface's.
PT_HD float spreadWeight(const EdgeStops& edges, const DenoiseSurface& q, float distance) {
    return fastExp(edges.logWeight(q, edges.inverseDepthScale(distance)));
}

// The variance of a pixel's mean estimated from its neighbours (a 7x7 window on the same
// surface), for the first samples, where each pixel's own estimate has too few samples to
// speak (SVGF section 4.2 does the same while a pixel's history is short): where the true
// image is smooth, neighbouring means differ by the noise of a mean. `neighbourAt(dx, dy,
// surface, luminance)` says whether the pixel (dx, dy) from the centre takes part (inside the
// image, not left out) and, where it does, gives its surface and luminance; the centre weighs
// 1. spatialVarianceAt reads the window from the images; the GPU from a tile in shared memory.
constexpr int kSpreadRadius = 3;
template <class NeighbourAt>
PT_HD float windowVariance(const EdgeStops& edges, const NeighbourAt& neighbourAt) {
    // The depth scale of each tap distance, by |dy| and |dx| (one division each, not one a tap;
    // [0][0], the centre's, is never read).
    float inverseDepth[kSpreadRadius + 1][kSpreadRadius + 1];
    PT_UNROLL
    for (int j = 0; j <= kSpreadRadius; ++j) {
        PT_UNROLL
        for (int i = 0; i <= kSpreadRadius; ++i)
            inverseDepth[j][i] = edges.inverseDepthScale(sqrtf(float(i * i + j * j)));
    }
    SpreadSums sums;
    PT_UNROLL
    for (int dy = -kSpreadRadius; dy <= kSpreadRadius; ++dy) {
        PT_UNROLL
        for (int dx = -kSpreadRadius; dx <= kSpreadRadius; ++dx) {
            DenoiseSurface q;
            float l;
            if (!neighbourAt(dx, dy, q, l)) continue;
            const float w =
                dx == 0 && dy == 0
                    ? 1.0f
                    : fastExp(edges.logWeight(q, inverseDepth[dy < 0 ? -dy : dy][dx < 0 ? -dx : dx]));
            sums.add(w, l);
        }
    }
    return sums.variance();
}

PT_HD float spatialVarianceAt(const DenoiseSample* in, const DenoiseSurface* surfaces,
                              const SurfaceStops* stops, uint32_t width, uint32_t height, uint32_t x,
                              uint32_t y) {
    const uint32_t p = y * width + x;
    if (!in[p].valid()) return kInvalid;
    return windowVariance(EdgeStops{surfaces[p], stops[p]},
                          [&](int dx, int dy, DenoiseSurface& surface, float& l) {
                              const int qx = int(x) + dx, qy = int(y) + dy;
                              if (qx < 0 || qy < 0 || qx >= int(width) || qy >= int(height)) return false;
                              const uint32_t q = uint32_t(qy) * width + uint32_t(qx);
                              if (!in[q].valid()) return false;
                              surface = loadSurface(surfaces, q);
                              l = luminance(in[q].radiance);
                              return true;
                          });
}

// The variance of a pixel's mean below kMinSamplesForOwnVariance samples, from its own
// estimate and its neighbours' (spatialVarianceAt), both raised by fewSamplesVariance: at one
// sample its own is 0 and the neighbours' stands alone; from two on, the geometric mean of the
// two. The neighbours' alone opened the luminance stops of a shadowed pixel beside a lit one (a
// shadow edge no guide shows is noise to the window), which took in its neighbours' light:
// DepthOfFieldExample at 640x480, 2 spp, had 3.1x the raw relMSE after denoising, 0.019x with
// the geometric mean (CPU backend, one seed; on the H200, three seeds: 1.9-11x above the raw
// error before, 10-34x below it after). Its own alone underestimates a pixel whose few samples
// agreed by chance.
// Denoised over raw relMSE, CPU backend, the mean over four seeds against 8192 spp
// (DepthOfFieldExample and GolfBall 160x120, Cornell box 128x128), at 2 / 3 spp:
//                        DepthOfField     GolfBall        Cornell
//   neighbours' alone    1.81  1.00       0.176  0.194    0.029  0.040
//   own alone            0.19  0.18       0.214  0.214    0.047  0.056
//   the smaller          0.20  0.19       0.221  0.223    0.044  0.053
//   geometric mean       0.22  0.19       0.197  0.209    0.041  0.050
// The geometric mean keeps DepthOfFieldExample's gain at the least cost to the others.
PT_HD float firstSamplesVariance(float own, float neighbours, uint32_t samples) {
    if (!(neighbours >= 0.0f) || samples < 2 || !(own >= 0.0f)) return neighbours;  // kInvalid stays
    return sqrtf(own) * sqrtf(neighbours);  // the product under one root could overflow or underflow
}

// Fireflies in the first samples. A pixel whose one sample found a rare bright path (a lamp
// through a gap, a caustic) holds most of a 1-spp image's error (one pixel of
// DepthOfFieldExample held 81% of it after denoising), and below kMinSamplesForOwnVariance
// samples the outlier weight cannot see it: its variance is its neighbours' spread
// (spatialVarianceAt), and every neighbour's spread holds it too. So before that estimate each
// pixel on a surface has its luminance held to the mean of its neighbours on a surface plus
// kFireflyDeviations of their spread, a 7x7 window without it. The window ignores the edge
// stops: at 1 spp they come from one sample's normal and depth, and on a defocused or bumpy
// surface they part a pixel from most of its neighbours (weighted by them, with at least 3 of
// weight, DepthOfFieldExample's ratio below came to 0.62). Energy is lost where a pixel truly
// outshines its neighbours, but only while own variances are too young to speak; from
// kMinSamplesForOwnVariance samples on, the outlier weight takes over. Denoised relMSE over the
// raw image's, the mean over seeds (DepthOfFieldExample 160x120, eight seeds, and its worst;
// GolfBall 160x120 and the Cornell box 128x128, four), CPU backend against 8192 spp, 1 spp:
//                                DepthOfField     GolfBall   Cornell
//   no clamp                     0.77 (1.40)      0.152      0.0242
//   radius 3, 1 deviation        0.37 (0.56)      0.141      0.0242
//   radius 3, 1.5 deviations     0.40 (0.61)      0.148      0.0224
//   radius 2, 1.5 deviations     0.38 (0.61)      0.148      0.0236
// At 2 spp (before firstSamplesVariance), radius 3 and 1.5 deviations: DepthOfField 1.23 to
// 1.20, GolfBall 0.182 to 0.176. Below 1.5 deviations a
// heavy-tailed first sample of one path in three finding the light (at three times the truth)
// is clamped too: that is the noise, not a firefly.
constexpr int kFireflyRadius = 3;
constexpr float kFireflyDeviations = 1.5f;
// Fewer neighbours on a surface than this (a corner, a small object against the sky): no clamp.
constexpr float kFireflyMinNeighbours = 8.0f;
constexpr float kNoLuminanceLimit = 3.4e38f;

// The luminance a pixel on a surface is held to (kNoLuminanceLimit: none). Two passes over the
// window, the mean and then the deviations from it: one pass of sums and sums of squares in
// floats lost three digits of a low-noise surface's spread (a spread of 1e-4 of the mean left
// the limit 1.3e-3 off, as far from the CPU's double box sums, firefly_limits.h).
// `neighbourAt(dx, dy, luminance)` says whether the pixel (dx, dy) from the centre takes part
// (inside the image, not left out, on a surface) and, where it does, gives its luminance;
// fireflyLimitAt reads the window from the images, the GPU from a tile in shared memory.
template <class NeighbourAt>
PT_HD float fireflyLimit(const NeighbourAt& neighbourAt) {
    // Calls f(luminance) for each neighbour that takes part.
    const auto forEachNeighbour = [&](const auto& f) {
        for (int dy = -kFireflyRadius; dy <= kFireflyRadius; ++dy) {
            for (int dx = -kFireflyRadius; dx <= kFireflyRadius; ++dx) {
                float l;
                if ((dx != 0 || dy != 0) && neighbourAt(dx, dy, l)) f(l);
            }
        }
    };
    float count = 0.0f, sum = 0.0f;
    forEachNeighbour([&](float l) {
        count += 1.0f;
        sum += l;
    });
    if (count < kFireflyMinNeighbours) return kNoLuminanceLimit;
    const float mean = sum / count;
    float squares = 0.0f;
    forEachNeighbour([&](float l) { squares += (l - mean) * (l - mean); });
    return mean + kFireflyDeviations * sqrtf(squares / count);
}

// Whether a sample takes part in the firefly windows: not left out, on a surface.
PT_HD bool inFireflyWindow(const DenoiseSample& sample, const DenoiseSurface& surface) {
    return sample.valid() && surface.depth > 0.0f;
}

// The luminance pixel (x, y) is held to.
PT_HD float fireflyLimitAt(const DenoiseSample* in, const DenoiseSurface* surfaces, uint32_t width,
                           uint32_t height, uint32_t x, uint32_t y) {
    const uint32_t p = y * width + x;
    if (!inFireflyWindow(in[p], surfaces[p])) return kNoLuminanceLimit;
    return fireflyLimit([&](int dx, int dy, float& l) {
        const int qx = int(x) + dx, qy = int(y) + dy;
        if (qx < 0 || qy < 0 || qx >= int(width) || qy >= int(height)) return false;
        const uint32_t q = uint32_t(qy) * width + uint32_t(qx);
        if (!inFireflyWindow(in[q], surfaces[q])) return false;
        l = luminance(in[q].radiance);
        return true;
    });
}

// A sample held to a luminance limit, scaled as a whole (it keeps its colour). Its variance
// stays: spatialVarianceAt replaces it below kMinSamplesForOwnVariance, and firstSamplesVariance
// takes it in from 2 spp, where keeping a clamped pixel's larger variance changed nothing
// measurable (a reviewer's 2-spp runs).
PT_HD DenoiseSample withoutFirefly(const DenoiseSample& s, float limit) {
    const float l = luminance(s.radiance);
    if (!s.valid() || !(l > limit) || !(l > 0.0f)) return s;
    return {s.radiance * (maxf(limit, 0.0f) / l), s.variance};
}

// What an a-trous pass reads of the variances around a centre p: `blurred`, p's variance blurred
// over 3x3 (SVGF eq. 5's g_3x3: the luminance edge stop should not follow the noise of the
// variance estimate itself), and `outlierLimit`, kOutlierVarianceRatio times the mean variance of
// p's eight neighbours (outlierWeight's yardstick).
struct NeighbourhoodVariance {
    float blurred, outlierLimit;
};

// A sample whose variance is more than this many times the mean of the centre's neighbours' is an
// outlier: a firefly, a pixel whose few samples found a rare bright path, which holds most of a
// noisy image's error and which the luminance stop, centred on the firefly's own value and widened
// by its own variance, kept (a firefly on DepthOfFieldExample went from 1540 to 720 against a truth
// of 11, 70% of that image's error after denoising at 16 spp). Such a sample's weight, its own and
// as a tap, is scaled by limit / variance: where the variances are alike (most pixels) no weight
// changes; a firefly whose variance is 1000x its neighbours' weighs a 500th of what it did as a
// centre, so its neighbours replace it. Its immediate neighbours, whose yardstick includes it, cut
// it less as a tap (about 4x in the first pass; the passes after thin out what it left). The ratio
// of variances does not fall as samples grow: a pixel whose true variance is more than twice its
// neighbours' (a penumbra, a caustic) stays weighed down, and there only the noise bound
// (boundedByNoise) makes the filter fade out. The variance carried along is still that of the
// weighted mean (SVGF eq. 4), with the new weights. Denoised over raw relMSE, CPU backend, the mean
// over four seeds against 8192 spp (Cornell box 4096 spp, 128x128; the others 160x120), at 1 / 4 /
// 16 spp:
//                       Cornell            DepthOfField       BarnLamp           GolfBall
//   no outlier weight   .028 .052 .107     1.42 .627 .462     .547 .387 .642     .164 .230 .356
//   ratio 1.5           .023 .063 .107     .657 .249 .118     .413 .269 .388     .148 .249 .356
//   ratio 2             .024 .059 .101     .731 .262 .127     .443 .269 .379     .152 .240 .342
//   ratio 3             .026 .054 .097     .843 .286 .134     .491 .284 .425     .155 .232 .337
//   2, first pass only  .025 .063 .107     .677 .258 .123     .422 .268 .401     .148 .245 .357
// Weights of limit / (variance + limit) instead (inverse-variance weighting, softened) gave .025
// .079 .142 on the Cornell box and .141 .267 .388 on GolfBall: weighing every pixel by its own
// noisy variance favours those whose few samples missed the light. On the H200 the weight costs 11%
// of a 1080p denoise (0.915 against 0.823 ms, medians of three alternated runs).
constexpr float kOutlierVarianceRatio = 2.0f;
constexpr float kNoOutlierLimit = 3.4e38f;  // no neighbours to compare with
constexpr float kMinOutlierWeight = 1e-4f;

// A sample's weight factor, limit / variance past the limit. Never below kMinOutlierWeight:
// where every neighbour's variance is 0 (a constant sky around a one-pixel object) the limit is
// 0. On the GPU the division is the approximate one (a reciprocal and a multiply, 2 ulp), a
// tap's weight needing no more; IEEE division there is a call-like sequence a tap.
PT_HD float outlierWeight(float variance, float outlierLimit) {
#if defined(__CUDA_ARCH__)
    float ratio;  // __fdividef without its denormal handling
    asm("div.approx.ftz.f32 %0, %1, %2;" : "=f"(ratio) : "f"(outlierLimit), "f"(variance));
#else
    const float ratio = outlierLimit / variance;
#endif
    return variance > outlierLimit ? maxf(ratio, kMinOutlierWeight) : 1.0f;
}

// The centre's own weight in an a-trous pass (the same on both backends, bit for bit).
PT_HD float centerWeight(float variance, float outlierLimit) {
    return splineWeight(0) * splineWeight(0) * outlierWeight(variance, outlierLimit);
}

// `deviationAt(dx, dy)`: the deviation of the pixel (dx, dy) from p, negative where it is left
// out or past the image's edge (it then weighs 0: no branch, so the CPU runs a row of these as
// vectors).
template <class DeviationAt>
PT_HD NeighbourhoodVariance neighbourhoodVarianceAt(const DeviationAt& deviationAt) {
    float sum = 0.0f, sumW = 0.0f, neighbours = 0.0f, neighbourCount = 0.0f;
    PT_UNROLL
    for (int dy = -1; dy <= 1; ++dy) {
        PT_UNROLL
        for (int dx = -1; dx <= 1; ++dx) {
            const float deviation = deviationAt(dx, dy);
            const bool in = deviation >= 0.0f;
            const float w = in ? (dx == 0 ? 2.0f : 1.0f) * (dy == 0 ? 2.0f : 1.0f) : 0.0f;  // 3x3 binomial
            const float variance = deviation * deviation;
            sum += w * variance;
            sumW += w;
            const bool neighbour = in & ((dx != 0) | (dy != 0));
            neighbours += neighbour ? variance : 0.0f;
            neighbourCount += neighbour ? 1.0f : 0.0f;
        }
    }
    return {sumW > 0.0f ? sum / sumW : 0.0f,
            neighbourCount > 0.0f ? kOutlierVarianceRatio * neighbours / neighbourCount : kNoOutlierLimit};
}

// 1 / the luminance difference that counts as one deviation at a centre: as a factor of the
// exponent, 0 for a left-out centre (the guides alone weigh its neighbours).
PT_HD float inverseLuminanceScale(bool centerValid, float blurredVariance) {
    return centerValid ? 1.0f / (kLuminanceSigma * sqrtf(blurredVariance) + 1e-10f) : 0.0f;
}

// The centre's scales for its taps: the luminance stop's and outlierWeight's (its
// NeighbourhoodVariance); the depth stop's depend on the tap's distance.
struct TapScales {
    float centerLuminance, inverseLuminance, outlierLimit;
};

// The weight of an a-trous tap at neighbour q (its surface, the luminance of its radiance, its
// deviation: negative where q is left out), `spline` the product of its B3-spline weights,
// inverseDepth the centre's depth scale for q's distance.
PT_HD float atrousTapWeight(const EdgeStops& edges, const DenoiseSurface& q, float inverseDepth,
                            float tapLuminance, float deviation, const TapScales& scales, float spline) {
    const float logWeight = edges.logWeight(q, inverseDepth) -
                            fabsf(tapLuminance - scales.centerLuminance) * scales.inverseLuminance;
    return deviation >= 0.0f
               ? spline * fastExp(logWeight) * outlierWeight(deviation * deviation, scales.outlierLimit)
               : 0.0f;
}

// What an a-trous pass adds up for one pixel.
struct AtrousSums {
    Vec3 radiance = Vec3(0.0f);
    float weight = 0.0f, variance = 0.0f;

    // `sampleVariance` counts for nothing where w is 0 (a left-out sample's may be anything).
    PT_HD void add(float w, Vec3 sampleRadiance, float sampleVariance) {
        radiance += w * sampleRadiance;
        weight += w;
        variance += w * w * sampleVariance;
    }
    // The weighted mean and its variance (SVGF eq. 4); left out where nothing had weight.
    PT_HD DenoiseSample result() const {
        if (!(weight > 0.0f)) return {Vec3(0.0f), kInvalid};
        return {radiance / weight, variance / (weight * weight)};
    }
};

// One a-trous iteration at pixel (x, y): 5x5 taps `step` pixels apart (step = 2^iteration).
// A left-out centre takes its neighbours' weighted mean (by the guides alone).
PT_HD PackedSample atrousAt(const PackedSample* in, const DenoiseSurface* surfaces, const SurfaceStops* stops,
                            uint32_t width, uint32_t height, uint32_t x, uint32_t y, uint32_t step) {
    const uint32_t p = y * width + x;
    const DenoiseSample center = unpackSample(in[p]);
    const EdgeStops edges{surfaces[p], stops[p]};
    // The depth scales of the taps' five distances, |i| and |j| in 0..2 (one division each, not
    // one a tap).
    float inverseDepth[3][3];
    PT_UNROLL
    for (int j = 0; j <= 2; ++j) {
        PT_UNROLL
        for (int i = 0; i <= 2; ++i)
            inverseDepth[j][i] = edges.inverseDepthScale(float(step) * sqrtf(float(i * i + j * j)));
    }
    const NeighbourhoodVariance around = neighbourhoodVarianceAt([&](int dx, int dy) {
        const bool inside = (dx >= 0 || x > 0) && (dx <= 0 || x + 1 < width) && (dy >= 0 || y > 0) &&
                            (dy <= 0 || y + 1 < height);
        return inside ? floatFromHalf(in[int(p) + dy * int(width) + dx].deviation) : kInvalid;
    });
    const TapScales scales{luminance(center.radiance), inverseLuminanceScale(center.valid(), around.blurred),
                           around.outlierLimit};
    AtrousSums sums;
    if (center.valid()) {
        sums.add(centerWeight(center.variance, around.outlierLimit), center.radiance, center.variance);
    }
    // Tap (i, j), whose sample and surface are `sample` and `surface`.
    const auto tap = [&](int i, int j, const PackedSample& sample, const DenoiseSurface& surface) {
        const Vec3 radiance(floatFromHalf(sample.r), floatFromHalf(sample.g), floatFromHalf(sample.b));
        const float deviation = floatFromHalf(sample.deviation);
        sums.add(atrousTapWeight(edges, surface, inverseDepth[j < 0 ? -j : j][i < 0 ? -i : i],
                                 luminance(radiance), deviation, scales, splineWeight(i) * splineWeight(j)),
                 radiance, deviation * deviation);
    };
    const uint32_t reach = 2 * step;
    if (x >= reach && y >= reach && x + reach < width && y + reach < height) {
        // All 25 taps inside the image (most pixels): no bounds to check, and a row of taps read
        // through one pointer a plane, each tap's offset from it a constant (on the GPU the
        // load's immediate, where a 32-bit index made two wide multiply-adds a tap). With it and
        // fastExp's and outlierWeight's flush-to-zero forms, a pass at 1080p on the H200 went
        // from 200 to 174 us (ncu; issue-bound, 0.86 of the issue slots), 46-48 instructions
        // a tap, and the whole 4-spp denoise from 0.96 to 0.87 ms (`pt-render bench`; with the
        // guides' 1 / n, aov.h, 0.85).
        const ptrdiff_t row = ptrdiff_t(width) * ptrdiff_t(step);
        PT_UNROLL
        for (int j = -2; j <= 2; ++j) {
            const PackedSample* rowSamples = in + p + j * row;
            const DenoiseSurface* rowSurfaces = surfaces + p + j * row;
            PT_UNROLL
            for (int i = -2; i <= 2; ++i) {
                const int column = i * int(step);
                if (i != 0 || j != 0)
                    tap(i, j, loadPacked(rowSamples, column), loadSurface(rowSurfaces, column));
            }
        }
    } else {
        PT_UNROLL
        for (int j = -2; j <= 2; ++j) {
            PT_UNROLL
            for (int i = -2; i <= 2; ++i) {
                const int qx = int(x) + i * int(step), qy = int(y) + j * int(step);
                if ((i != 0 || j != 0) && qx >= 0 && qy >= 0 && qx < int(width) && qy < int(height)) {
                    const uint32_t q = uint32_t(qy) * width + uint32_t(qx);
                    tap(i, j, loadPacked(in, q), loadSurface(surfaces, q));
                }
            }
        }
    }
    return packSample(sums.result());
}

}  // namespace denoise
}  // namespace pt
