// Which batches a kernel uses on its ISA. Most kernels are written for rows of at most 8 float
// lanes (an 8x8 tile row is one AVX2 batch): on the avx512 ISA they run on 256-bit batches, an
// architecture of their own (`avx512_256`) that behaves as AVX2 with FMA in xsimd and is compiled
// with AVX-512 F/CD/DQ/BW/VL, so the compiler may use EVEX encodings, 32 vector registers and mask
// registers. Kernels generalized over their lane count ask for the ISA's full width instead.
#pragma once

#include <xsimd/xsimd.hpp>

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

#if defined(__AVX512F__) && defined(__AVX512CD__) && defined(__AVX512DQ__) && \
    defined(__AVX512BW__) && defined(__AVX512VL__) && defined(__FMA__)
// AVX2 and FMA batches on a CPU with AVX-512: a type apart from xsimd::fma3<xsimd::avx2>, so that
// no inline function is shared with the AVX2 objects, which are compiled without AVX-512.
struct avx512_256 : xsimd::fma3<xsimd::avx2> {
  static constexpr bool supported() noexcept { return true; }
  static constexpr bool available() noexcept { return true; }
  static constexpr char const* name() noexcept { return "avx512_256"; }
};
#define EDGEWISE_HAS_AVX512_256 1
#endif

// RowArch<A>: the batches of kernels written for at most 8 lanes, on the ISA whose xsimd
// architecture is A.
template <class IsaArch>
struct RowArchOf {
  using type = IsaArch;
};
// WideArch<A>: the batches of kernels generalized over their lane count, from the batches A
// their callers use.
template <class Arch>
struct WideArchOf {
  using type = Arch;
};
#if defined(EDGEWISE_HAS_AVX512_256)
template <>
struct RowArchOf<xsimd::avx512bw> {
  using type = avx512_256;
};
template <>
struct WideArchOf<avx512_256> {
  using type = xsimd::avx512bw;
};
#endif
template <class IsaArch>
using RowArch = typename RowArchOf<IsaArch>::type;
template <class Arch>
using WideArch = typename WideArchOf<Arch>::type;

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE

#if defined(EDGEWISE_HAS_AVX512_256)
namespace xsimd::types {
XSIMD_DECLARE_SIMD_REGISTER_ALIAS(edgewise::EDGEWISE_ISA_NAMESPACE::avx512_256, fma3<avx2>);
}
#endif
