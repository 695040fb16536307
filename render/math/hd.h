#pragma once
// PT_HD marks per-ray code that both backends compile: g++ for the CPU backend and nvcc
// for the CUDA one. Code under this macro uses no std containers, exceptions, virtual
// calls or allocation (STYLE.md rule 1).
#if defined(__CUDACC__)
#define PT_HD __host__ __device__ __forceinline__
#else
#define PT_HD inline
#endif
