// Compiles what follows, to avx2_target_end.h, for AVX2 (issue 21's runtime-dispatched walks,
// wide_walk_simd.h): included by a .cpp after every header it shares with SSE2 code, whose
// inline functions must stay SSE2 code in that object too (the linker may keep any one copy of
// an inline function). No include guard: each begin is closed by an end.
#if defined(PT_AVX2_TARGET_PRAGMA)
#error "avx2_target_begin.h: already inside an AVX2 region"
#endif
#define PT_AVX2_TARGET_PRAGMA 1
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2,fma"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#endif
