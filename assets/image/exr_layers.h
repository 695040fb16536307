#pragma once
// Layered EXR: the beauty of a render and its AOVs (render/integrator/aov.h) in ONE OpenEXR
// file, one channel group per AOV, in a single part: the layout Nuke, Blender, OIIO's tools and
// most EXR viewers show as layers ("layer.channel"; the beauty is the unnamed layer).
//
// Channel naming, by what the AOV holds (colours RGB, vectors XYZ, depth Z, scalars Y):
//   beauty                      R G B A                 (scene-linear Rec.709; A = 1)
//   albedo, emission            <aov>.R <aov>.G <aov>.B
//   shading_normal, geometric_normal, position
//                               <aov>.X <aov>.Y <aov>.Z  (world space)
//   depth                       depth.Z                  (Nuke's depth channel name)
//   uv                          uv.U uv.V
//   roughness, metallic, instance_id, material_id, sample_count, variance
//                               <aov>.Y                  (Y: OpenEXR's one grey channel)
//   bvh_cost                    bvh_cost.nodes bvh_cost.primitives
//   alpha                       alpha.A                  (A: OpenEXR's alpha channel)
//   the denoised beauty         denoised.R denoised.G denoised.B   (render/denoise/; the raw
//                               beauty stays in R G B)
// Values are Backend::readAov's, unchanged: channel i of a layer is component i of its RGBA.
//
// Pixel types: the precision (half or float) applies to every channel except these, which
// are 32-bit float in every file:
//   instance_id, material_id, sample_count: integers that must stay exact. Float holds every
//     integer up to 2^24 exactly (half only up to 2048) and keeps -1, the id of a camera ray
//     that missed, as readAov gives it; UINT would need another miss value, and compositors
//     convert UINT channels to float anyway.
//   depth, position: world-space distances; half's 11-bit mantissa puts neighbouring values
//     0.5 units apart past 1024, too coarse for depth-of-field or relighting in compositing.
// Half channels saturate at +-65504, the largest half, instead of overflowing to infinity.
//
// Metadata: the caller's string attributes (renderMetadata, cameraMetadata, OCIO config and
// view, ...), plus pt:aovs, the AOV layers in the file ("albedo,depth"; "" for none).
//
// Writing and reading need OpenImageIO; with PT_OIIO=OFF both throw InputError.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "assets/image/image_write.h"
#include "render/backend/aov.h"
#include "render/backend/rendered_images.h"
#include "render/scene/scene.h"

namespace pt {

enum class ExrPixelType { Half, Float, Uint };

// One channel as written: values[pixel * stride] for pixels in row-major order, top row first.
struct ExrChannelSource {
    std::string name;
    ExrPixelType type = ExrPixelType::Float;
    const float* values = nullptr;
    size_t stride = 1;
};

// Channel i named names[i] takes component i of each pixel of `pixels`, `stride` floats apart.
std::vector<ExrChannelSource> interleavedChannels(const std::vector<std::string>& names, ExrPixelType type,
                                                  const float* pixels, size_t stride);

// The names of the channels AOV `aov` is written as, in order (the table above).
std::vector<std::string> aovExrChannelNames(Aov aov);
// The pixel type `aov`'s channels get in a file of `precision` (Half or Float).
ExrPixelType aovExrPixelType(Aov aov, ExrPixelType precision);

struct LayeredExr {
    uint32_t width = 0, height = 0;
    std::vector<float> beauty;                     // RGBA float, as Backend::readBeauty gives it
    std::vector<AovImage> aovs;                    // at most one image per AOV
    ExrPixelType precision = ExrPixelType::Float;  // Half or Float
    ImageMetadata metadata;
    std::vector<float>
        denoised;  // RGBA float (Backend::readDenoised), written as denoised.R/G/B; empty: none
};

// Writes `image` (atomically: temp file, then rename) with the channels above, zip-compressed.
// Throws InputError naming `path` on failure, on images of the wrong size and on an AOV given
// twice.
void writeLayeredExr(const std::string& path, const LayeredExr& image);

// Writes any set of channels as one EXR, atomically (what writeLayeredExr and writeExr share).
void writeExrChannels(const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannelSource>& channels, const ImageMetadata& metadata);

// A render's images (render/backend/rendered_images.h) as a layered EXR, with `metadata`
// followed by cameraMetadata(camera) (image_metadata.h).
LayeredExr layeredExr(RenderedImages images, ExrPixelType precision, const Camera& camera,
                      ImageMetadata metadata);

// A comma-separated list of AOV names ("albedo,depth"; "all" stands for every AOV) as a mask.
// Throws InputError for an empty list or name, or an unknown name, listing the valid names.
AovMask parseAovList(const std::string& list);
// The inverse: the names of `mask`'s AOVs in the enum's order, joined by `separator`.
std::string aovListText(AovMask mask, const std::string& separator = ",");

// An EXR read back channel by channel (tests, tools): values as float, in OIIO's channel order
// (R G B A first, then the layers by name).
struct ExrChannelData {
    std::string name;
    ExrPixelType type = ExrPixelType::Float;
    std::vector<float> values;  // one per pixel, row-major, top row first
};

struct ExrImage {
    uint32_t width = 0, height = 0;
    std::vector<ExrChannelData> channels;
    ImageMetadata metadata;

    const ExrChannelData* channel(const std::string& name) const;  // nullptr when absent
    std::string attribute(const std::string& key) const;           // "" when absent
};

// Throws InputError naming `path` when it cannot be read or holds a channel type EXR does not
// have (half, float, uint).
ExrImage readExrChannels(const std::string& path);

}  // namespace pt
