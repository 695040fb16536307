#pragma once
// The operations of triangle_lanes.inl's lane vocabularies (namespace lane_ops in
// triangle_block_intersect.h at SSE2 and in wide_walk_avx2.h at AVX2) that differ only in their
// intrinsics' prefix, _mm or _mm256: expanded inside each vocabulary, after its `Vector`. The
// comparisons stay with each, whose predicates are spelt differently.
#define PT_LANE_ARITHMETIC(prefix)                                                                \
    inline Vector set1(float a) { return prefix##_set1_ps(a); }                                   \
    inline Vector zero() { return prefix##_setzero_ps(); }                                        \
    inline Vector load(const float* p) { return prefix##_load_ps(p); }                            \
    inline void store(float* p, Vector a) { prefix##_store_ps(p, a); }                            \
    inline Vector add(Vector a, Vector b) { return prefix##_add_ps(a, b); }                       \
    inline Vector sub(Vector a, Vector b) { return prefix##_sub_ps(a, b); }                       \
    inline Vector mul(Vector a, Vector b) { return prefix##_mul_ps(a, b); }                       \
    inline Vector div(Vector a, Vector b) { return prefix##_div_ps(a, b); }                       \
    inline Vector bitAnd(Vector a, Vector b) { return prefix##_and_ps(a, b); }                    \
    inline Vector bitOr(Vector a, Vector b) { return prefix##_or_ps(a, b); }                      \
    inline Vector bitXor(Vector a, Vector b) { return prefix##_xor_ps(a, b); }                    \
    inline Vector bitAndNot(Vector a, Vector b) { return prefix##_andnot_ps(a, b); } /* ~a & b */ \
    inline int mask(Vector a) { return prefix##_movemask_ps(a); }
