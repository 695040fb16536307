#include "pt_render/gen/gen_scene.h"

#include <algorithm>
#include <cmath>

#include "render/math/affine.h"

namespace pt::cli {

Vec4 lookRotation(Vec3 forward, Vec3 upHint) {
    const Vec3 z = -normalize(forward);
    Vec3 x = cross(upHint, z);
    if (!(length(x) > 1e-6f)) x = cross(Vec3(1.0f, 0.0f, 0.0f), z);
    x = normalize(x);
    const Vec3 y = cross(z, x);
    // Shepperd's method on the matrix with columns x, y, z: divide by the largest of the four
    // candidate diagonals so the square root never meets a value near zero.
    const float m00 = x.x, m11 = y.y, m22 = z.z, trace = m00 + m11 + m22;
    Vec4 q;
    if (trace > 0.0f) {
        const float s = 2.0f * std::sqrt(1.0f + trace);
        q = {(y.z - z.y) / s, (z.x - x.z) / s, (x.y - y.x) / s, 0.25f * s};
    } else if (m00 > m11 && m00 > m22) {
        const float s = 2.0f * std::sqrt(1.0f + m00 - m11 - m22);
        q = {0.25f * s, (y.x + x.y) / s, (z.x + x.z) / s, (y.z - z.y) / s};
    } else if (m11 > m22) {
        const float s = 2.0f * std::sqrt(1.0f + m11 - m00 - m22);
        q = {(y.x + x.y) / s, 0.25f * s, (z.y + y.z) / s, (z.x - x.z) / s};
    } else {
        const float s = 2.0f * std::sqrt(1.0f + m22 - m00 - m11);
        q = {(z.x + x.z) / s, (z.y + y.z) / s, 0.25f * s, (x.y - y.x) / s};
    }
    const float norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    return {q.x / norm, q.y / norm, q.z / norm, q.w / norm};
}

GenCamera frameSphere(Vec3 centre, float radius, Vec3 towardCamera) {
    GenCamera camera;
    // The loader's default image is square, so the vertical field of view is the narrower one.
    const double distance = 1.05 * radius / std::sin(0.5 * camera.yfovRadians);
    camera.node.translation = centre + normalize(towardCamera) * float(distance);
    camera.node.rotation = lookRotation(-towardCamera, Vec3(0.0f, 1.0f, 0.0f));
    camera.znear = std::max(0.5 * (distance - radius), 1e-3 * distance);
    return camera;
}

GenCamera frameBox(Vec3 lo, Vec3 hi, Vec3 towardCamera) {
    GenCamera camera;
    const Vec3 centre = (lo + hi) * 0.5f, back = normalize(towardCamera);
    const Vec4 rotation = lookRotation(-back, Vec3(0.0f, 1.0f, 0.0f));
    const Affine3 frame = rotationTransform(rotation);
    const Vec3 right = frame.transformVector({1.0f, 0.0f, 0.0f}),
               up = frame.transformVector({0.0f, 1.0f, 0.0f});
    const double tanHalf = std::tan(0.5 * camera.yfovRadians);
    // A corner at offset o from the centre is in view when the camera's distance along `back`
    // is at least o.back + max(|o.right|, |o.up|) / tan(fov / 2).
    double distance = 0.0, nearest = 1e30;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        const Vec3 o = p - centre;
        const double spread = std::max(std::abs(dot(o, right)), std::abs(dot(o, up)));
        distance = std::max(distance, double(dot(o, back)) + spread / tanHalf);
    }
    distance *= 1.05;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        nearest = std::min(nearest, distance - double(dot(p - centre, back)));
    }
    camera.node.translation = centre + back * float(distance);
    camera.node.rotation = rotation;
    camera.znear = std::max(0.5 * nearest, 1e-3 * distance);
    return camera;
}

std::vector<GenLight> defaultLights() {
    GenLight key;
    key.name = "key";
    key.node.rotation = lookRotation(Vec3(1.0f, -0.8f, -0.3f), Vec3(0.0f, 1.0f, 0.0f));
    key.color[1] = 0.96;
    key.color[2] = 0.9;
    key.intensity = 3.0;
    GenLight fill;
    fill.name = "fill";
    fill.node.rotation = lookRotation(Vec3(-0.7f, 0.3f, -0.6f), Vec3(0.0f, 1.0f, 0.0f));
    fill.color[0] = 0.8;
    fill.color[1] = 0.88;
    fill.intensity = 0.6;
    return {key, fill};
}

}  // namespace pt::cli
