// The float32 interpolators compiled for avx2.
#if !defined(__AVX2__) || !defined(__FMA__)
#error "fast_interpolation_avx2.cpp must be compiled with -mavx2 -mfma"
#endif

#define EDGEWISE_ISA_NAMESPACE isa_test_avx2
#define EDGEWISE_ISA_ENUM Isa::avx2
#define EDGEWISE_ARCH xsimd::fma3<xsimd::avx2>
#include "fast_interpolation-inl.hpp"
