#include "render/backend/rendered_images.h"

#include "render/backend/backend.h"

namespace pt {

std::vector<AovImage> readAovImages(const Backend& backend, AovMask wanted) {
    std::vector<AovImage> images;
    const AovMask available = wanted & backend.aovs();
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (!(available & aovBit(Aov(i)))) continue;
        images.push_back({Aov(i), {}});
        backend.readAov(Aov(i), images.back().rgba);
    }
    return images;
}

RenderedImages readRenderedImages(const Backend& backend, AovMask wanted) {
    RenderedImages images{backend.width(), backend.height(), {}, readAovImages(backend, wanted)};
    backend.readBeauty(images.beauty);
    return images;
}

}  // namespace pt
