// The kernels every ISA defines in its own namespace, one translation unit per capability
// (kernels/<capability>/<capability>_kernels.cpp), gathered into its table by
// kernel_table_kernels.cpp: the list of kernel_table.hpp, declared. Included after isa_build.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kernel_table.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Each kernel of the list (kernel_table.hpp) declared with its function type.
#define EDGEWISE_DECLARE_KERNEL(name, type) std::type_identity_t<type> name;
EDGEWISE_FOR_EACH_KERNEL(EDGEWISE_DECLARE_KERNEL)
#undef EDGEWISE_DECLARE_KERNEL

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
