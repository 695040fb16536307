#pragma once
// Affine3: a 3x4 row-major affine transform (rotation/scale/shear in the 3x3 part,
// translation in the last column). Instances store object-to-world and its inverse;
// normals go through the transpose of the inverse.
#include "render/math/vec.h"

namespace pt {

struct Affine3 {
    // rows[r] = (m[r][0], m[r][1], m[r][2], t[r])
    Vec4 rows[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

    PT_HD float at(int r, int c) const {
        const Vec4& row = rows[r];
        return c == 0 ? row.x : c == 1 ? row.y : c == 2 ? row.z : row.w;
    }
    PT_HD Vec3 transformPoint(Vec3 p) const {
        return {rows[0].x * p.x + rows[0].y * p.y + rows[0].z * p.z + rows[0].w,
                rows[1].x * p.x + rows[1].y * p.y + rows[1].z * p.z + rows[1].w,
                rows[2].x * p.x + rows[2].y * p.y + rows[2].z * p.z + rows[2].w};
    }
    PT_HD Vec3 transformVector(Vec3 v) const {
        return {rows[0].x * v.x + rows[0].y * v.y + rows[0].z * v.z,
                rows[1].x * v.x + rows[1].y * v.y + rows[1].z * v.z,
                rows[2].x * v.x + rows[2].y * v.y + rows[2].z * v.z};
    }
    // For a normal: call on the *inverse* transform; multiplies by its transpose.
    PT_HD Vec3 transformNormalByInverse(Vec3 n) const {
        return {rows[0].x * n.x + rows[1].x * n.y + rows[2].x * n.z,
                rows[0].y * n.x + rows[1].y * n.y + rows[2].y * n.z,
                rows[0].z * n.x + rows[1].z * n.y + rows[2].z * n.z};
    }
    // |M| v for v >= 0: the linear part with each entry replaced by its magnitude. Bounds,
    // per axis, what the transform makes of per-axis magnitudes or error bounds.
    PT_HD Vec3 transformMagnitude(Vec3 v) const {
        return {fabsf(rows[0].x) * v.x + fabsf(rows[0].y) * v.y + fabsf(rows[0].z) * v.z,
                fabsf(rows[1].x) * v.x + fabsf(rows[1].y) * v.y + fabsf(rows[1].z) * v.z,
                fabsf(rows[2].x) * v.x + fabsf(rows[2].y) * v.y + fabsf(rows[2].z) * v.z};
    }
    PT_HD Vec3 translation() const { return {rows[0].w, rows[1].w, rows[2].w}; }
    // Determinant of the linear part: negative means the transform mirrors (flips winding).
    PT_HD float determinant() const {
        return rows[0].x * (rows[1].y * rows[2].z - rows[1].z * rows[2].y) -
               rows[0].y * (rows[1].x * rows[2].z - rows[1].z * rows[2].x) +
               rows[0].z * (rows[1].x * rows[2].y - rows[1].y * rows[2].x);
    }
};

PT_HD bool isFinite(const Affine3& m) {
    for (const Vec4& row : m.rows) {
        if (!isFinite(row.x) || !isFinite(row.y) || !isFinite(row.z) || !isFinite(row.w)) return false;
    }
    return true;
}

PT_HD Affine3 operator*(const Affine3& a, const Affine3& b) {
    Affine3 r;
    for (int i = 0; i < 3; ++i) {
        float v[4];
        for (int j = 0; j < 4; ++j) {
            v[j] = a.at(i, 0) * b.at(0, j) + a.at(i, 1) * b.at(1, j) + a.at(i, 2) * b.at(2, j) +
                   (j == 3 ? a.at(i, 3) : 0.0f);
        }
        r.rows[i] = {v[0], v[1], v[2], v[3]};
    }
    return r;
}

PT_HD Affine3 inverse(const Affine3& m) {
    const float det = m.determinant();
    const float s = 1.0f / det;
    Affine3 r;
    const float a = m.at(0, 0), b = m.at(0, 1), c = m.at(0, 2);
    const float d = m.at(1, 0), e = m.at(1, 1), f = m.at(1, 2);
    const float g = m.at(2, 0), h = m.at(2, 1), i = m.at(2, 2);
    const Vec3 r0{(e * i - f * h) * s, (c * h - b * i) * s, (b * f - c * e) * s};
    const Vec3 r1{(f * g - d * i) * s, (a * i - c * g) * s, (c * d - a * f) * s};
    const Vec3 r2{(d * h - e * g) * s, (b * g - a * h) * s, (a * e - b * d) * s};
    const Vec3 t = m.translation();
    r.rows[0] = {r0.x, r0.y, r0.z, -dot(r0, t)};
    r.rows[1] = {r1.x, r1.y, r1.z, -dot(r1, t)};
    r.rows[2] = {r2.x, r2.y, r2.z, -dot(r2, t)};
    return r;
}

PT_HD Affine3 translationTransform(Vec3 t) {
    Affine3 r;
    r.rows[0].w = t.x;
    r.rows[1].w = t.y;
    r.rows[2].w = t.z;
    return r;
}

PT_HD Affine3 scaleTransform(Vec3 s) {
    Affine3 r;
    r.rows[0].x = s.x;
    r.rows[1].y = s.y;
    r.rows[2].z = s.z;
    return r;
}

// Rotation by a unit quaternion (x, y, z, w), glTF's convention.
PT_HD Affine3 rotationTransform(Vec4 q) {
    const float x = q.x, y = q.y, z = q.z, w = q.w;
    Affine3 r;
    r.rows[0] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0};
    r.rows[1] = {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0};
    r.rows[2] = {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0};
    return r;
}

}  // namespace pt
