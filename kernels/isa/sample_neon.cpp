// The sampling kernels compiled for neon.
#if !defined(__aarch64__) || !defined(__ARM_NEON)
#error "sample_neon.cpp must be compiled with an AArch64 compiler"
#endif

#define EDGEWISE_ISA_NAMESPACE isa_neon
#define EDGEWISE_ISA_ENUM Isa::neon
#define EDGEWISE_ARCH xsimd::neon64
#include "../generic/sample_batch-inl.hpp"
