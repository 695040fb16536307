#include "assets/image/image_metadata.h"

#include <cstdio>

#include "assets/image/image_read_format.h"
#include "assets/image/pfm_file.h"
#include "assets/input_error.h"
#include "render/integrator/camera.h"
#if PT_HAVE_OIIO
#include "assets/image/oiio_image_io.h"
#endif

namespace pt {
namespace {

std::string numbers(std::initializer_list<float> values) {
    std::string text;
    for (float v : values) {
        char number[32];
        std::snprintf(number, sizeof number, "%.9g", double(v));
        text += (text.empty() ? "" : " ") + std::string(number);
    }
    return text;
}

std::string vec3Text(Vec3 v) { return numbers({v.x, v.y, v.z}); }

}  // namespace

ImageMetadata readImageMetadata(const std::string& path) {
    if (isPfmPath(path)) return {};  // the format has none
#if PT_HAVE_OIIO
    return oiioImageIo().readImageMetadata(path);
#else
    throw InputError(needsOpenImageIoMessage(path, lowercaseExtension(path)));
#endif
}

ImageMetadata cameraMetadata(const Camera& camera, uint32_t width, uint32_t height) {
    const RenderCamera rc = makeRenderCamera(camera, width, height);
    const Vec3 x = normalize(rc.right), y = normalize(rc.up), z = -rc.forward, o = rc.origin;
    return {{"pt:camera_position", vec3Text(camera.position)},
            {"pt:camera_look_at", vec3Text(camera.lookAt)},
            {"pt:camera_up", vec3Text(camera.up)},
            {"pt:camera_vertical_fov_deg", numbers({camera.verticalFovDegrees})},
            {"pt:camera_aperture_radius", numbers({rc.lensRadius})},
            {"pt:camera_focus_distance", numbers({rc.focusDistance})},
            {"pt:camera_to_world",
             numbers({x.x, y.x, z.x, o.x, x.y, y.y, z.y, o.y, x.z, y.z, z.z, o.z, 0.0f, 0.0f, 0.0f, 1.0f})}};
}

}  // namespace pt
