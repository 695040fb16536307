#pragma once
// Small float vectors for per-ray code. Deliberately not GLM: these are the only vector
// types the kernels see, so the CPU and CUDA builds round the same way.
#include <cmath>
#include <cstdint>

#include "render/math/hd.h"

namespace pt {

struct Vec2 {
    float x = 0, y = 0;
    constexpr Vec2() = default;
    PT_HD constexpr Vec2(float x_, float y_) : x(x_), y(y_) {}
    PT_HD float operator[](int i) const { return i == 0 ? x : y; }
};

struct Vec3 {
    float x = 0, y = 0, z = 0;
    constexpr Vec3() = default;
    PT_HD constexpr explicit Vec3(float s) : x(s), y(s), z(s) {}
    PT_HD constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    PT_HD float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    PT_HD float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

struct Vec4 {
    float x = 0, y = 0, z = 0, w = 0;
    constexpr Vec4() = default;
    PT_HD constexpr Vec4(float x_, float y_, float z_, float w_) : x(x_), y(y_), z(z_), w(w_) {}
    PT_HD Vec3 xyz() const { return {x, y, z}; }
};

PT_HD Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
PT_HD Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
PT_HD Vec2 operator*(Vec2 a, float s) { return {a.x * s, a.y * s}; }
PT_HD Vec2 operator*(float s, Vec2 a) { return {a.x * s, a.y * s}; }

PT_HD Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
PT_HD Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PT_HD Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
PT_HD Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
PT_HD Vec3 operator/(Vec3 a, Vec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
PT_HD Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
PT_HD Vec3 operator*(float s, Vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
PT_HD Vec3 operator/(Vec3 a, float s) { return a * (1.0f / s); }
PT_HD Vec3& operator+=(Vec3& a, Vec3 b) {
    a = a + b;
    return a;
}
PT_HD Vec3& operator-=(Vec3& a, Vec3 b) {
    a = a - b;
    return a;
}
PT_HD Vec3& operator*=(Vec3& a, Vec3 b) {
    a = a * b;
    return a;
}
PT_HD Vec3& operator*=(Vec3& a, float s) {
    a = a * s;
    return a;
}
PT_HD bool operator==(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
PT_HD bool operator!=(Vec3 a, Vec3 b) { return !(a == b); }

PT_HD float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
PT_HD Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
PT_HD float lengthSquared(Vec3 a) { return dot(a, a); }
PT_HD float length(Vec3 a) { return sqrtf(dot(a, a)); }
PT_HD Vec3 normalize(Vec3 a) { return a * (1.0f / length(a)); }
// min/max as comparisons: g++ without -ffast-math calls libm for fminf/fmaxf (their NaN
// rules have no single SSE instruction), which cost ~8% of a render. For a NaN in `a` these
// return `b`, as fminf/fmaxf do; a NaN in `b` is passed on, which the callers' own NaN
// guards catch.
PT_HD float minf(float a, float b) { return a < b ? a : b; }
PT_HD float maxf(float a, float b) { return a > b ? a : b; }
PT_HD Vec3 vmin(Vec3 a, Vec3 b) { return {minf(a.x, b.x), minf(a.y, b.y), minf(a.z, b.z)}; }
PT_HD Vec3 vmax(Vec3 a, Vec3 b) { return {maxf(a.x, b.x), maxf(a.y, b.y), maxf(a.z, b.z)}; }
PT_HD Vec3 vabs(Vec3 a) { return {fabsf(a.x), fabsf(a.y), fabsf(a.z)}; }
PT_HD float maxComponent(Vec3 a) { return maxf(a.x, maxf(a.y, a.z)); }
PT_HD float minComponent(Vec3 a) { return minf(a.x, minf(a.y, a.z)); }
PT_HD int maxDimension(Vec3 a) { return a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2); }
PT_HD float luminance(Vec3 rgb) { return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z; }
PT_HD bool isFinite(float a) {
#if defined(__CUDA_ARCH__)
    return isfinite(a);
#else
    return std::isfinite(a);
#endif
}
PT_HD bool isInfinite(float a) {
#if defined(__CUDA_ARCH__)
    return isinf(a);
#else
    return std::isinf(a);
#endif
}
PT_HD bool isFinite(Vec3 a) { return isFinite(a.x) && isFinite(a.y) && isFinite(a.z); }
PT_HD bool isBlack(Vec3 a) { return a.x == 0.0f && a.y == 0.0f && a.z == 0.0f; }
PT_HD Vec3 lerp(Vec3 a, Vec3 b, float t) { return a * (1.0f - t) + b * t; }
// NaN clamps to `lo`, as fminf(fmaxf(v, lo), hi) would.
PT_HD float clampf(float v, float lo, float hi) { return v > lo ? (v < hi ? v : hi) : lo; }

// Reflects `v` (pointing away from the surface) about `n`.
PT_HD Vec3 reflect(Vec3 v, Vec3 n) { return 2.0f * dot(v, n) * n - v; }

// The bit pattern of a float, and back; used to nudge floats by whole ULPs.
PT_HD int32_t floatAsInt(float f) {
#if defined(__CUDA_ARCH__)
    return __float_as_int(f);
#else
    int32_t i;
    __builtin_memcpy(&i, &f, sizeof(i));
    return i;
#endif
}
PT_HD float intAsFloat(int32_t i) {
#if defined(__CUDA_ARCH__)
    return __int_as_float(i);
#else
    float f;
    __builtin_memcpy(&f, &i, sizeof(f));
    return f;
#endif
}

// c ? a : b without a branch, where c is data that a branch would mispredict (a ray's largest
// axis, the sign of its direction: coin tosses for diffuse bounces). GCC turns such selects of
// floats into jumps; on the host the bits are masked in instead. The device's selects cost no
// branch.
PT_HD float selectFloat(bool c, float a, float b) {
#if defined(__CUDA_ARCH__)
    return c ? a : b;
#else
    const int32_t mask = -int32_t(c);
    return intAsFloat((floatAsInt(a) & mask) | (floatAsInt(b) & ~mask));
#endif
}

// v[i] for i in 0..2 without a branch on i (selectFloat), where operator[]'s selects become
// jumps.
PT_HD float componentAt(Vec3 v, int i) { return selectFloat(i == 0, v.x, selectFloat(i == 1, v.y, v.z)); }

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 0.31830988618379067154f;
constexpr float kInf = __builtin_huge_valf();

}  // namespace pt
