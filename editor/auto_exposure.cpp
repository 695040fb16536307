#include "editor/auto_exposure.h"

#include <algorithm>
#include <cmath>

#include "render/math/vec.h"

namespace pt::editor {

float autoExposureStops(const std::vector<float>& rgba) {
    double sumLog = 0.0;
    size_t counted = 0;
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        const double y = double(luminance(Vec3(rgba[i], rgba[i + 1], rgba[i + 2])));
        if (!(y > 0.0) || !std::isfinite(y)) continue;
        sumLog += std::log(y);
        ++counted;
    }
    if (counted == 0) return 0.0f;
    const double logAverage = sumLog / double(counted);
    const double stops = (std::log(double(kMiddleGrey)) - logAverage) / std::log(2.0);
    return float(std::clamp(stops, -double(kMaxAutoExposureStops), double(kMaxAutoExposureStops)));
}

}  // namespace pt::editor
