#pragma once
// PT_HD marks per-ray code that both backends compile: g++ for the CPU backend and nvcc
// for the CUDA one. Code under this macro uses no std containers, exceptions, virtual
// calls or allocation (STYLE.md rule 1).
#if defined(__CUDACC__)
#define PT_HD __host__ __device__ __forceinline__
#else
#define PT_HD inline
#endif

// PT_HD_OUTLINED marks a large per-ray function that many call sites share (texture lookups):
// the CUDA device code keeps one out-of-line copy instead of inlining it at every call, which
// kept the megakernel far larger than the instruction cache (issue 13: seven inlined texture
// lookups were 13,700 of the textured megakernel's 33,800 SASS instructions). Callers pass it
// values and plain pointers, never the RenderScene kernel parameter, whose address would force
// a copy of it into local memory. Host code inlines as usual.
#if defined(__CUDA_ARCH__)
#define PT_HD_OUTLINED __host__ __device__ inline __noinline__
#elif defined(__CUDACC__)
#define PT_HD_OUTLINED __host__ __device__ inline
#else
#define PT_HD_OUTLINED inline
#endif

// PT_UNROLL before a loop of a small constant trip count unrolls it on both compilers, so that
// small arrays indexed by its counter stay in registers and its per-iteration constants fold
// (the denoiser's 5x5 taps: on the GPU, a loop not unrolled kept its table of depth scales in
// local memory).
// PT_NO_UNROLL keeps a loop rolled on the GPU, where unrolling would keep every iteration's
// values live at once (the compressed walk's two halves of a node).
#if defined(__CUDA_ARCH__)
#define PT_UNROLL _Pragma("unroll")
#define PT_NO_UNROLL _Pragma("unroll 1")
#elif defined(__CUDACC__)
#define PT_UNROLL  // the host side of a .cu file: nvcc's front end knows neither pragma there
#define PT_NO_UNROLL
#else
#define PT_UNROLL _Pragma("GCC unroll 8")
#define PT_NO_UNROLL
#endif
