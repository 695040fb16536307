#pragma once
// Auto exposure: the stops that bring a frame's log-average luminance to middle grey, the "key"
// of Reinhard et al. 2002 ("Photographic Tone Reproduction for Digital Images", eq. 1 and 2,
// key 0.18). A sunlit scene in physical units (a 6830-lux sun) needs about -11 stops, past the
// end of where a slider is comfortable; one click finds it.
#include <vector>

namespace pt::editor {

constexpr float kMiddleGrey = 0.18f;
constexpr float kMaxAutoExposureStops = 24.0f;

// `rgba`: linear RGBA floats. Pixels that are black (the empty sky of a scene without an
// environment) or not finite are left out of the average; 0 where none is left.
float autoExposureStops(const std::vector<float>& rgba);

}  // namespace pt::editor
