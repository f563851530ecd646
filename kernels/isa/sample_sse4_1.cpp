// The sampling kernels compiled for sse4_1.
#if !defined(__SSE4_1__) || defined(__AVX__)
#error "sample_sse4_1.cpp must be compiled with -msse4.1 (no AVX)"
#endif

#define EDGEWISE_ISA_NAMESPACE isa_sse4_1
#define EDGEWISE_ISA_ENUM Isa::sse4_1
#define EDGEWISE_ARCH xsimd::sse4_1
#include "../generic/sample_batch-inl.hpp"
