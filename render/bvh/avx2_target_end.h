// Closes the AVX2 region that avx2_target_begin.h opened.
#if !defined(PT_AVX2_TARGET_PRAGMA)
#error "avx2_target_end.h: no AVX2 region to close"
#endif
#undef PT_AVX2_TARGET_PRAGMA
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
