// The sampling kernels compiled for sse2.
#if !defined(__SSE2__) || defined(__SSE3__) || defined(__AVX__)
#error "sample_sse2.cpp must be compiled with -msse2 only (no SSE3, no AVX)"
#endif

#define EDGEWISE_ISA_NAMESPACE isa_sse2
#define EDGEWISE_ISA_ENUM Isa::sse2
#define EDGEWISE_ARCH xsimd::sse2
#include "../generic/sample_batch-inl.hpp"
