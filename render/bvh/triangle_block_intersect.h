#pragma once
// The watertight triangle test (triangle_intersect.h; Woop, Benthin and Wald 2013) on the four
// triangles of a TriangleBlock at once with SSE (issue 21), and the leaf functor of the CPU's
// wide walk over such blocks. Each lane performs the scalar test's operations in the scalar
// test's order (no FMA: the host builds with -ffp-contract=off, and the products are separate
// _mm_mul_ps), so every lane's t, u and v equal intersectTriangle's bit for bit, and hits stay
// those of the binary walk, of brute force and of the GPU. Embree tests its leaves four or eight
// triangles at a time the same way; here the SoA copy also spares the scalar test's three
// dependent loads (primitive index, vertex indices, positions) per triangle.
#if defined(__CUDACC__)
#error "triangle_block_intersect.h is CPU code: CUDA translation units test one triangle at a time"
#endif
#include <emmintrin.h>

#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/hit.h"
#include "render/kernel/triangle_block.h"

namespace pt {

// The scalar test's rare exact-zero branch for lane `lane`: edge functions redone in double.
inline void exactEdgesOfLane(float (&e)[3][TriangleBlock::kWidth], const float (&x)[3][TriangleBlock::kWidth],
                             const float (&y)[3][TriangleBlock::kWidth], uint32_t lane) {
    const double ax = x[0][lane], ay = y[0][lane], bx = x[1][lane], by = y[1][lane];
    const double cx = x[2][lane], cy = y[2][lane];
    e[0][lane] = float(cx * by - cy * bx);
    e[1][lane] = float(ax * cy - ay * cx);
    e[2][lane] = float(bx * ay - by * ax);
}

// intersectTriangle(ray, tMax, ...) on the block's four lanes: the lanes that hit, as a 4-bit
// mask, with their t, u and v.
inline int intersectTriangleBlock(const WatertightRay& ray, float tMax, const TriangleBlock& block, __m128& t,
                                  __m128& u, __m128& v) {
    const __m128 originX = _mm_set1_ps(ray.origin[ray.kx]), originY = _mm_set1_ps(ray.origin[ray.ky]);
    const __m128 originZ = _mm_set1_ps(ray.origin[ray.kz]);
    const __m128 sx = _mm_set1_ps(ray.sx), sy = _mm_set1_ps(ray.sy), sz = _mm_set1_ps(ray.sz);
    // Per corner: a = p - origin in the ray's axes, then sheared (ax = a[kx] - sx * a[kz]).
    __m128 x[3], y[3], z[3];
    for (int c = 0; c < 3; ++c) {
        const __m128 ax = _mm_sub_ps(_mm_load_ps(block.corner[c][ray.kx]), originX);
        const __m128 ay = _mm_sub_ps(_mm_load_ps(block.corner[c][ray.ky]), originY);
        z[c] = _mm_sub_ps(_mm_load_ps(block.corner[c][ray.kz]), originZ);
        x[c] = _mm_sub_ps(ax, _mm_mul_ps(sx, z[c]));
        y[c] = _mm_sub_ps(ay, _mm_mul_ps(sy, z[c]));
    }
    // edgeFunction(a, b, c, d) = a * b - c * d, each product rounded on its own.
    const auto edge = [](__m128 a, __m128 b, __m128 c, __m128 d) {
        return _mm_sub_ps(_mm_mul_ps(a, b), _mm_mul_ps(c, d));
    };
    __m128 e0 = edge(x[2], y[1], y[2], x[1]);  // weight of p0
    __m128 e1 = edge(x[0], y[2], y[0], x[2]);  // weight of p1
    __m128 e2 = edge(x[1], y[0], y[1], x[0]);  // weight of p2
    const __m128 zero = _mm_setzero_ps();
    const int zeroEdge = _mm_movemask_ps(
        _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(e0, zero), _mm_cmpeq_ps(e1, zero)), _mm_cmpeq_ps(e2, zero)));
    if (zeroEdge != 0) {
        alignas(16) float e[3][TriangleBlock::kWidth], xs[3][TriangleBlock::kWidth],
            ys[3][TriangleBlock::kWidth];
        _mm_store_ps(e[0], e0), _mm_store_ps(e[1], e1), _mm_store_ps(e[2], e2);
        for (int c = 0; c < 3; ++c) _mm_store_ps(xs[c], x[c]), _mm_store_ps(ys[c], y[c]);
        for (int lanes = zeroEdge; lanes != 0; lanes &= lanes - 1) {
            exactEdgesOfLane(e, xs, ys, uint32_t(__builtin_ctz(unsigned(lanes))));
        }
        e0 = _mm_load_ps(e[0]), e1 = _mm_load_ps(e[1]), e2 = _mm_load_ps(e[2]);
    }
    // Mixed signs: the ray passes outside an edge.
    const __m128 negative =
        _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(e0, zero), _mm_cmplt_ps(e1, zero)), _mm_cmplt_ps(e2, zero));
    const __m128 positive =
        _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(e0, zero), _mm_cmpgt_ps(e1, zero)), _mm_cmpgt_ps(e2, zero));
    const __m128 det = _mm_add_ps(_mm_add_ps(e0, e1), e2);
    __m128 valid = _mm_andnot_ps(_mm_and_ps(negative, positive), _mm_cmpneq_ps(det, zero));
    if (_mm_movemask_ps(valid) == 0) return 0;
    const __m128 scaledT =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(e0, _mm_mul_ps(sz, z[0])), _mm_mul_ps(e1, _mm_mul_ps(sz, z[1]))),
                   _mm_mul_ps(e2, _mm_mul_ps(sz, z[2])));
    // det < 0 ? -scaledT : scaledT, and |det|, by the sign bit (det is never zero here).
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 signedT = _mm_xor_ps(scaledT, _mm_and_ps(det, sign));
    const __m128 absDet = _mm_andnot_ps(sign, det);
    const __m128 range = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(tMax), absDet), _mm_set1_ps(1.0f + 0x1p-20f));
    valid = _mm_and_ps(valid, _mm_and_ps(_mm_cmpgt_ps(signedT, zero), _mm_cmple_ps(signedT, range)));
    if (_mm_movemask_ps(valid) == 0) return 0;
    const __m128 invDet = _mm_div_ps(_mm_set1_ps(1.0f), det);
    t = _mm_mul_ps(scaledT, invDet);
    valid = _mm_and_ps(valid, _mm_and_ps(_mm_cmpgt_ps(t, zero), _mm_cmplt_ps(t, _mm_set1_ps(tMax))));
    u = _mm_mul_ps(e1, invDet);
    v = _mm_mul_ps(e2, invDet);
    return _mm_movemask_ps(valid);
}

// Leaf functor of walkWideBvh for a BLAS of triangles whose wide leaves index TriangleBlocks
// (`first` the first block, `count` its triangles, four a block, in consecutive blocks). The
// same hit as BlasLeaf's over the same primitives: the closest t, ties to the lower primitive,
// which does not depend on the order the lanes are looked at in. Every triangle of a block is
// tested, so all count as tested, also where an any-hit query stops at the first.
template <class Count>
struct TriangleBlockLeaf {
    const TriangleBlock* blocks;  // RenderScene::blasTriangleBlocks
    const TraversalRay& ray;
    Hit& hit;
    Count counter;
    bool anyHit;

    bool hitHere = false;  // this walk has found a hit: tMax is that hit's t

    bool operator()(uint32_t first, uint32_t count, float& tMax) {
        bool found = false;
        for (uint32_t b = 0; b * TriangleBlock::kWidth < count; ++b) {
            if (testBlock(blocks[first + b], count - b * TriangleBlock::kWidth, tMax)) {
                found = true;
                if (anyHit) return true;
            }
        }
        return found;
    }

    // One block, of which `count` lanes (at most all four) are triangles of the leaf.
    bool testBlock(const TriangleBlock& block, uint32_t count, float& tMax) {
        for (uint32_t i = 0; i < count && i < TriangleBlock::kWidth; ++i) counter.primitive();
        const float limit = hitHere ? intAsFloat(floatAsInt(tMax) + 1) : tMax;  // t == tMax too
        __m128 t, u, v;
        int lanes = intersectTriangleBlock(ray.watertight, limit, block, t, u, v);
        if (lanes == 0) return false;
        alignas(16) float ts[TriangleBlock::kWidth], us[TriangleBlock::kWidth], vs[TriangleBlock::kWidth];
        _mm_store_ps(ts, t), _mm_store_ps(us, u), _mm_store_ps(vs, v);
        bool found = false;
        for (; lanes != 0; lanes &= lanes - 1) {
            const uint32_t lane = uint32_t(__builtin_ctz(unsigned(lanes)));
            const uint32_t primitive = block.primitive[lane];
            if (ts[lane] < tMax || (hitHere && ts[lane] == tMax && primitive < hit.primitive)) {
                hit.t = ts[lane], hit.u = us[lane], hit.v = vs[lane], hit.primitive = primitive;
                tMax = ts[lane];
                found = hitHere = true;
                if (anyHit) return true;
            }
        }
        return found;
    }
};

}  // namespace pt
