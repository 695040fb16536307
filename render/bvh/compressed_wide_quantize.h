#pragma once
// The quantised boxes of a compressed wide node (render/kernel/compressed_wide_node.h), from the
// binary nodes its slots were collapsed from. Shared by the host collapse and the CUDA refit,
// so a refitted node is quantised exactly as a freshly built one.
//
// Why the boxes stay conservative: the walk computes a plane's distance as
// fma(q, 2^e / d, (origin - o) / d), three roundings where the binary slab test has two (the
// GPU's form, compressedSlotHits in compressed_wide_walk.h, one more, which it accounts for), and
// the error of (origin - o) / d scales with the distance from the grid's origin rather than
// with the plane's own distance. Each plane is therefore placed at least one grid step
// outside the exact box (floor - 1, ceil + 1), which covers that error with a wide margin
// (about 500 u of a step), while the slab test's exit scale (1 + 2 gamma(3)) covers the part
// relative to the distance, as in the binary walk (Ize 2013). The grid step is at least 8 ulps
// of the coordinates, so the origin two steps below the box stays distinct from its corner.
#include <cstdint>

#include "render/kernel/bvh_node.h"
#include "render/kernel/compressed_wide_node.h"

namespace pt {

// Marks an unused slot in a compressed node's per-slot source list.
constexpr uint32_t kNoSourceNode = 0xffffffffu;

// The biased exponent of the smallest power of two >= x (x >= 0, finite), kept to normal floats.
PT_HD uint32_t exponentAtLeast(float x) {
    const uint32_t bits = uint32_t(floatAsInt(x));
    uint32_t e = bits >> 23;
    if ((bits & 0x7fffffu) != 0) ++e;
    return e < 1u ? 1u : (e > 254u ? 254u : e);
}

PT_HD float exponentStep(uint32_t exponent) { return intAsFloat(int32_t(exponent << 23)); }

// The grid's step, and a factor that divides by it exactly: 1 / step where that is a normal
// float (a multiplication, not a division, for each of a node's 48 planes), else 0 to divide.
struct GridStep {
    float step, inverse;
};
PT_HD GridStep gridStep(uint32_t exponent) {
    return {exponentStep(exponent), exponent <= 253u ? exponentStep(254u - exponent) : 0.0f};
}
PT_HD float inSteps(float distance, GridStep g) {
    return g.inverse != 0.0f ? distance * g.inverse : distance / g.step;
}

// Grid steps from origin of a lower (upper) box plane: rounded down (up) with a step of margin,
// kept to 0..255. Distances are clamped to [-1, 256] first (NaN to -1), which changes no
// result and lets an integer conversion round them: floorf and ceilf are library calls on
// x86-64 without SSE4.1, and a collapse rounds 48 planes a node.
PT_HD uint8_t quantizeLower(float plane, float origin, GridStep g) {
    const float steps = clampf(inSteps(plane - origin, g), -1.0f, 256.0f);
    const float truncated = float(int32_t(steps));
    const float below = truncated > steps ? truncated - 1.0f : truncated;  // floor
    return uint8_t(clampf(below - 1.0f, 0.0f, 255.0f));
}
PT_HD uint8_t quantizeUpper(float plane, float origin, GridStep g) {
    const float steps = clampf(inSteps(plane - origin, g), -1.0f, 256.0f);
    const float truncated = float(int32_t(steps));
    const float above = truncated < steps ? truncated + 1.0f : truncated;  // ceil
    return uint8_t(clampf(above + 1.0f, 0.0f, 255.0f));
}

// Sets node's origin, exponents and boxes from binary[slotSources[s]] for each used slot s
// (kNoSourceNode: unused; its box is left at zero: the walk ignores slots with neither an
// interior bit nor a leaf count). The grid spans the union of the used boxes in 250 steps.
PT_HD void quantizeWideBoxes(CompressedWideNode& node, const BvhNode* binary, const uint32_t* slotSources) {
    Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
        if (slotSources[s] == kNoSourceNode) continue;
        lo = vmin(lo, binary[slotSources[s]].lo);
        hi = vmax(hi, binary[slotSources[s]].hi);
    }
    GridStep step[3];
    for (int a = 0; a < 3; ++a) {
        const bool empty = !(lo[a] <= hi[a]);
        const float extent = empty ? 0.0f : hi[a] - lo[a];
        const float magnitude = empty ? 0.0f : fmaxf(fabsf(lo[a]), fabsf(hi[a]));
        const uint32_t e = exponentAtLeast(fmaxf(extent * (1.0f / 250.0f), magnitude * (1.0f / (1 << 20))));
        step[a] = gridStep(e);
        node.exponent[a] = uint8_t(e);
        node.origin[a] = empty ? 0.0f : lo[a] - 2.0f * step[a].step;
    }
    for (uint32_t s = 0; s < CompressedWideNode::kWidth; ++s) {
        const bool used = slotSources[s] != kNoSourceNode;
        for (uint32_t a = 0; a < 3; ++a) {
            const auto lower = CompressedWideNode::BoxPlane(CompressedWideNode::kLoX + a);
            const auto upper = CompressedWideNode::BoxPlane(CompressedWideNode::kHiX + a);
            node.plane(lower, s) =
                used ? quantizeLower(binary[slotSources[s]].lo[int(a)], node.origin[int(a)], step[a]) : 0;
            node.plane(upper, s) =
                used ? quantizeUpper(binary[slotSources[s]].hi[int(a)], node.origin[int(a)], step[a]) : 0;
        }
    }
}

}  // namespace pt
