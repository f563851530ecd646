// The scalar reference's kernels: the list of kernel_table.hpp declared in namespace
// edgewise::reference, as isa_kernels.hpp declares each ISA's. Each is defined beside its
// capability's reference (coverage_reference.cpp, pixel_area_reference.cpp,
// resolve_reference.cpp, sample_reference.cpp, vertex_stage_reference.cpp, draw_reference.cpp,
// occlusion_reference.cpp), and reference_kernel_table.cpp gathers them into the reference's
// table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kernel_table.hpp"

namespace edgewise::reference {

// Each kernel of the list (kernel_table.hpp) declared with its function type.
#define EDGEWISE_DECLARE_KERNEL(name, type) std::type_identity_t<type> name;
EDGEWISE_FOR_EACH_KERNEL(EDGEWISE_DECLARE_KERNEL)
#undef EDGEWISE_DECLARE_KERNEL

}  // namespace edgewise::reference
