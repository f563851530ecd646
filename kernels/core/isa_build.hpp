// Included first by every translation unit that is compiled once per ISA
// (edgewise_add_isa_objects() in cmake/isas.cmake): turns the EDGEWISE_BUILD_ISA=<name> it is
// compiled with into the names its kernels use.
//   EDGEWISE_ISA_NAMESPACE  isa_<name>, the namespace that keeps each ISA's inline code apart
//                           (defined beforehand to choose another, as the tests do)
//   EDGEWISE_ISA_ENUM       Isa::<name>
//   EDGEWISE_ARCH           the ISA's xsimd architecture (isa_list.hpp)
#pragma once

#ifndef EDGEWISE_BUILD_ISA
#error "per-ISA sources are compiled by edgewise_add_isa_objects() (cmake/isas.cmake)"
#endif

#include <xsimd/xsimd.hpp>

#include "edgewise/isa.hpp"
#include "isa_list.hpp"

#define EDGEWISE_CONCAT_NAMES(a, b) a##b
#define EDGEWISE_CONCAT(a, b) EDGEWISE_CONCAT_NAMES(a, b)
#ifndef EDGEWISE_ISA_NAMESPACE
#define EDGEWISE_ISA_NAMESPACE EDGEWISE_CONCAT(isa_, EDGEWISE_BUILD_ISA)
#endif
#define EDGEWISE_ISA_ENUM ::edgewise::Isa::EDGEWISE_BUILD_ISA
#define EDGEWISE_ARCH ::edgewise::detail::IsaArch<EDGEWISE_ISA_ENUM>::type

namespace edgewise::detail {

template <Isa>
struct IsaArch;
#define EDGEWISE_ISA_ARCH(name, arch, cpu_check) \
  template <>                                    \
  struct IsaArch<Isa::name> {                    \
    using type = arch;                           \
  };
EDGEWISE_FOR_EACH_SIMD_ISA(EDGEWISE_ISA_ARCH)
#undef EDGEWISE_ISA_ARCH

}  // namespace edgewise::detail

// Without its ISA's flags (cmake/isas.cmake), the file would silently build another ISA's code.
static_assert(EDGEWISE_ARCH::supported(), "compiled without the flags of its ISA");
