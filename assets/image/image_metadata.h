#pragma once
// Image attributes: reading back the string attributes writeExr and writeLayeredExr store
// (e.g. pt:spp, pt:noise_relmse of a reference render), for tools that compare against a
// render; and the attributes that describe a render's camera. Reading goes through
// OpenImageIO; the PT_OIIO=OFF build, which cannot read EXR, throws InputError.
#include <cstdint>
#include <string>

#include "assets/image/image_write.h"
#include "render/scene/scene.h"

namespace pt {

// Every attribute of the image's header as text. Throws InputError naming `path`.
ImageMetadata readImageMetadata(const std::string& path);

// The camera of a width x height render, numbers as text ("x y z" for vectors, 9 significant
// digits, so floats survive the round trip):
//   pt:camera_position, pt:camera_look_at, pt:camera_up   as the scene gives them
//   pt:camera_vertical_fov_deg, pt:camera_aperture_radius (world units; 0: pinhole)
//   pt:camera_focus_distance   the distance in focus (the look-at distance where the scene
//                              gives none)
//   pt:camera_to_world         4x4 row-major, camera space to world space, camera space as in
//                              glTF and OpenGL: x right, y up, looking down -z, unit axes
ImageMetadata cameraMetadata(const Camera& camera, uint32_t width, uint32_t height);

}  // namespace pt
