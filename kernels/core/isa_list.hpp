// The instruction sets, listed once for the code (cmake/isas.cmake lists them for the build;
// tests/core/isa_dispatch_test.cpp fails if the two lists disagree). Everything per ISA follows
// from these lists: compiled_isas(), the CPU checks, name_of(), the kernel tables and the dispatch.
#pragma once

#include "edgewise/isa.hpp"

// Every value of the Isa enum, in its order: X(name).
#define EDGEWISE_FOR_EACH_ISA(X) X(reference) X(sse2) X(sse4_1) X(avx2) X(avx512) X(neon)

// The vectorized ISAs compiled for the target processor, worst first, as
// X(name, xsimd architecture, whether this CPU runs it). The reference, compiled everywhere, is
// not among them. GCC's __builtin_cpu_supports includes the OS's support for the wider
// registers (XGETBV).
#if defined(__x86_64__) || defined(_M_X64)
#define EDGEWISE_FOR_EACH_SIMD_ISA(X) \
  EDGEWISE_ISA_SSE2(X) EDGEWISE_ISA_SSE4_1(X) EDGEWISE_ISA_AVX2(X) EDGEWISE_ISA_AVX512(X)
// A build configured with EDGEWISE_ONLY_ISAS (cmake/isas.cmake) defines EDGEWISE_LEAVE_OUT_<name>
// for each ISA it does not compile.
#ifdef EDGEWISE_LEAVE_OUT_sse2
#define EDGEWISE_ISA_SSE2(X)
#else
#define EDGEWISE_ISA_SSE2(X) X(sse2, xsimd::sse2, __builtin_cpu_supports("sse2"))
#endif
#ifdef EDGEWISE_LEAVE_OUT_sse4_1
#define EDGEWISE_ISA_SSE4_1(X)
#else
#define EDGEWISE_ISA_SSE4_1(X) X(sse4_1, xsimd::sse4_1, __builtin_cpu_supports("sse4.1"))
#endif
#ifdef EDGEWISE_LEAVE_OUT_avx2
#define EDGEWISE_ISA_AVX2(X)
#else
#define EDGEWISE_ISA_AVX2(X) \
  X(avx2, xsimd::fma3<xsimd::avx2>, __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
#endif
#ifdef EDGEWISE_LEAVE_OUT_avx512
#define EDGEWISE_ISA_AVX512(X)
#else
#define EDGEWISE_ISA_AVX512(X)                                                      \
  X(avx512, xsimd::avx512bw,                                                        \
    __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&              \
        __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&  \
        __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") && \
        __builtin_cpu_supports("avx512vl"))
#endif
#elif defined(__aarch64__)
// Advanced SIMD is mandatory on AArch64.
#define EDGEWISE_FOR_EACH_SIMD_ISA(X) X(neon, xsimd::neon64, true)
#else
#error "edgewise: no ISA list for this processor (kernels/core/isa_list.hpp)"
#endif
