// kernel_table(Isa): the table of each compiled ISA, from isa_list.hpp.
#include "kernel_table.hpp"

namespace edgewise::detail {

const KernelTable& kernel_table(Isa isa) {
  switch (isa) {
#define EDGEWISE_TABLE_CASE(name, arch, cpu_check) \
  case Isa::name:                                  \
    return isa_##name::kernel_table();
    EDGEWISE_FOR_EACH_SIMD_ISA(EDGEWISE_TABLE_CASE)
#undef EDGEWISE_TABLE_CASE
    default:
      return isa_reference::kernel_table();
  }
}

}  // namespace edgewise::detail
