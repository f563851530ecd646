// The sampling kernels compiled for avx2.
#if !defined(__AVX2__) || !defined(__FMA__)
#error "sample_avx2.cpp must be compiled with -mavx2 -mfma"
#endif

#define EDGEWISE_ISA_NAMESPACE isa_avx2
#define EDGEWISE_ISA_ENUM Isa::avx2
#define EDGEWISE_ARCH xsimd::fma3<xsimd::avx2>
#include "../generic/sample_batch-inl.hpp"
