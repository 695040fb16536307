#include "render/lights/environment_distribution.h"

#include <cmath>

#include "render/materials/texture_sample.h"

namespace pt {

namespace {

// Luminance of texel (x, y) after wrapping, as environmentRadiance() reads it (linear).
float texelLuminance(const Texture& image, int x, int y) {
    const int w = int(image.width), h = int(image.height);
    const size_t i =
        (size_t(wrapTexel(y, h, image.wrapT)) * size_t(w) + size_t(wrapTexel(x, w, image.wrapS))) * 4;
    Vec3 c;
    if (image.format == TexelFormat::RGBA32F) {
        c = {image.texelsF[i], image.texelsF[i + 1], image.texelsF[i + 2]};
    } else {
        c = Vec3(image.texels8[i], image.texels8[i + 1], image.texels8[i + 2]) * (1.0f / 255.0f);
    }
    const float l = luminance(c);
    return std::isfinite(l) && l > 0.0f ? l : 0.0f;  // negative or NaN texels never attract samples
}

// Mean of the image's reconstruction over pixel cell (x, y): bilinear filtering blends each
// texel with its neighbours, with weights 1/8, 3/4, 1/8 along each axis over the cell.
float cellLuminance(const Texture& image, int x, int y) {
    if (image.nearest) return texelLuminance(image, x, y);
    constexpr float kWeights[3] = {0.125f, 0.75f, 0.125f};
    float sum = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            sum += kWeights[dx + 1] * kWeights[dy + 1] * texelLuminance(image, x + dx, y + dy);
        }
    }
    return sum;
}

}  // namespace

EnvironmentDistribution buildEnvironmentDistribution(const Texture& image) {
    EnvironmentDistribution d;
    const uint32_t w = image.width, h = image.height;
    if (w == 0 || h == 0) return d;
    std::vector<double> f(size_t(w) * h);
    std::vector<double> rowSums(h, 0.0);
    double total = 0.0, luminanceSum = 0.0, sinSum = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        const double sinTheta = std::sin(kPi * (double(y) + 0.5) / double(h));
        for (uint32_t x = 0; x < w; ++x) {
            const double l = cellLuminance(image, int(x), int(y));
            f[size_t(y) * w + x] = l * sinTheta;
            rowSums[y] += l * sinTheta;
        }
        total += rowSums[y];
        luminanceSum += rowSums[y];
        sinSum += sinTheta * w;
    }
    if (!(total > 0.0) || !std::isfinite(total)) return d;
    d.width = w;
    d.height = h;
    d.averageLuminance = luminanceSum / sinSum;
    const double mean = total / (double(w) * h);
    d.pdf.resize(size_t(w) * h);
    for (size_t i = 0; i < f.size(); ++i) d.pdf[i] = float(f[i] / mean);
    d.marginalCdf.resize(h + 1);
    d.conditionalCdf.resize(size_t(h) * (w + 1));
    double running = 0.0;
    for (uint32_t y = 0; y < h; ++y) {
        d.marginalCdf[y] = float(running / total);
        running += rowSums[y];
        float* row = &d.conditionalCdf[size_t(y) * (w + 1)];
        double rowRunning = 0.0;
        for (uint32_t x = 0; x < w; ++x) {
            // An empty row is never picked (zero marginal width); give it a uniform CDF anyway.
            row[x] = rowSums[y] > 0.0 ? float(rowRunning / rowSums[y]) : float(x) / float(w);
            rowRunning += f[size_t(y) * w + x];
        }
        row[w] = 1.0f;
    }
    d.marginalCdf[h] = 1.0f;
    return d;
}

}  // namespace pt
