#pragma once
// Scene edits the robustness suite makes at run time, where a file would be large (a million
// triangles) or where the case needs the exact numbers it put in (the environment image).
#include <cstdint>

#include "render/math/vec.h"
#include "render/scene/scene.h"

namespace pt::cli {

// Scales the whole scene about the origin by `scale`, then moves it by `offset`: instances,
// punctual lights and the camera (aperture and focus distance scale too), so the image is
// unchanged in exact arithmetic. Radiance is scale-free; point and spot intensities (W/sr)
// are kept, which scales their irradiance by 1/scale^2, so scenes with them are not for this.
void scaleAndMoveScene(Scene& scene, float scale, Vec3 offset);
// The scene as moving it by `offset` leaves it, moved back: every translation (and the
// camera) rounded to the floats that lie near `offset`, at the origin again. Moving back is
// exact (a float minus another within a factor of two of it), so this is the very geometry
// the moved scene has, without the magnitude; the baseline that tells the renderer's own
// error at that magnitude from the scene's.
void roundAsIfMoved(Scene& scene, Vec3 offset);

// `count` random triangles with vertices inside the cube of side `side` centred at `center`,
// as one new mesh and instance of material `material` (which must exist).
void addTriangleSoup(Scene& scene, uint32_t count, Vec3 center, float side, const std::string& material);

// An equirectangular environment of `width` x `height` texels of radiance `sky`, except one
// texel of radiance `sun` in row `sunRow` (row 0 looks up, +Y).
struct SunEnvironment {
    uint32_t width = 256, height = 128, sunRow = 31, sunColumn = 64;
    float sky = 0.5f, sun = 1e4f;
};
void setSunEnvironment(Scene& scene, const SunEnvironment& environment);

// The radiance of a white Lambertian floor (normal +Y, albedo 1) under that environment: the
// cosine-weighted integral of the sky over the upper hemisphere is pi * sky, and the sun texel
// adds sun * cos(theta) * solid angle, with the solid angle of a texel at polar angle theta
// 2 pi^2 sin(theta) / (width * height); the floor's radiance is the irradiance over pi.
double floorRadianceUnder(const SunEnvironment& environment);

}  // namespace pt::cli
