// The ISA's kernel table: every kernel of its objects (isa_kernels.hpp), compiled once per ISA.
#include "isa_build.hpp"

#include "isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

const detail::KernelTable& kernel_table() {
  // Designated: the compiler checks each kernel against its member's name, type and order.
#define EDGEWISE_KERNEL_ENTRY(name, type) .name = &name,
  static constexpr detail::KernelTable table{.isa = EDGEWISE_ISA_ENUM,
                                             EDGEWISE_FOR_EACH_KERNEL(EDGEWISE_KERNEL_ENTRY)};
#undef EDGEWISE_KERNEL_ENTRY
  return table;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
