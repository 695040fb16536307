#pragma once
// What a backend holds now, read out as plain images (issue 16): writers in assets/ are handed
// these and never reach into a live Backend.
#include <cstdint>
#include <vector>

#include "render/backend/aov.h"

namespace pt {

class Backend;

// An AOV as Backend::readAov gives it: RGBA float, the beauty's size.
struct AovImage {
    Aov aov = Aov::Albedo;
    std::vector<float> rgba;
};

struct RenderedImages {
    uint32_t width = 0, height = 0;
    std::vector<float> beauty;   // RGBA float, as Backend::readBeauty gives it
    std::vector<AovImage> aovs;  // at most one image per AOV
};

// The AOVs of `wanted` that `backend` accumulates now (Backend::aovs()), read through readAov,
// in the enum's order. AOVs wanted but not accumulated are left out.
std::vector<AovImage> readAovImages(const Backend& backend, AovMask wanted);

// The beauty and readAovImages(backend, wanted).
RenderedImages readRenderedImages(const Backend& backend, AovMask wanted);

}  // namespace pt
