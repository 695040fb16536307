#pragma once
// Error of a rendered image against a reference, the figures `pt-render converge` and
// `pt-render stress` report and the editor plots live. Pure functions over float RGBA images
// (row-major, 4 floats a pixel, as Backend::readBeauty gives them); only R, G and B count (the
// alpha of a render is always 1 and would dilute the means).
#include <cstddef>
#include <vector>

namespace pt {

// Added to r^2 in the relMSE denominator (and to |r| in the percentage error) so that black
// reference pixels do not divide by zero; 1e-2 is the usual choice (Rousselle et al., "Robust
// denoising using feature and color information", 2013) and makes relMSE close to an absolute
// MSE where the reference is darker than about 0.1.
constexpr double kRelativeErrorEpsilon = 1e-2;

struct ImageError {
    double relMse = 0.0;  // mean over pixels and RGB of (x - r)^2 / (r^2 + 1e-2)
    double rmse = 0.0;    // sqrt(mean of (x - r)^2), in the image's units of radiance
    double mape = 0.0;    // mean of |x - r| / (|r| + 1e-2), in percent
};

// Throws std::invalid_argument when the sizes differ or are not a whole number of pixels.
ImageError imageError(const std::vector<float>& image, const std::vector<float>& reference);

// The relMSE and RMSE that per-channel noise of variance `variance` (RGBA layout, e.g. the
// variance of a mean estimated from independent batches) adds in expectation against
// `reference`: mean of v / (r^2 + 1e-2), and sqrt(mean of v).
struct NoiseLevel {
    double relMse = 0.0;
    double rmse = 0.0;
};
NoiseLevel noiseLevel(const std::vector<float>& variance, const std::vector<float>& reference);

// Mean of each of R, G and B over the image, as {r, g, b}.
std::vector<double> channelMeans(const std::vector<float>& image);

// Every value of the RGB channels finite.
bool allFinite(const std::vector<float>& image);

}  // namespace pt
