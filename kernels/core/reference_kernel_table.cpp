// The scalar reference as a kernel table, like every ISA's: the kernels of the list
// (kernel_table.hpp), each defined beside its capability's reference in namespace
// edgewise::reference (reference_kernels.hpp). They compute in exact integers or double precision
// where the result allows it (the vertex stage's float32 results are defined by its scalar
// operations); sampled values are rounded to float only on the way out.
#include "reference_kernels.hpp"

namespace edgewise::isa_reference {

const detail::KernelTable& kernel_table() {
  // Designated: the compiler checks each kernel against its member's name, type and order.
#define EDGEWISE_KERNEL_ENTRY(name, type) .name = &reference::name,
  static constexpr detail::KernelTable table{.isa = Isa::reference,
                                             EDGEWISE_FOR_EACH_KERNEL(EDGEWISE_KERNEL_ENTRY)};
#undef EDGEWISE_KERNEL_ENTRY
  return table;
}

}  // namespace edgewise::isa_reference
