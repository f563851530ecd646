#include "fast_interpolation.hpp"

#include "core/isa_list.hpp"

#define EDGEWISE_DECLARE_TEST_TABLE(name, arch, cpu_check) \
  namespace edgewise::isa_test_##name {                    \
    const test::FastInterpolation& fast_interpolation();   \
  }
EDGEWISE_FOR_EACH_SIMD_ISA(EDGEWISE_DECLARE_TEST_TABLE)
#undef EDGEWISE_DECLARE_TEST_TABLE

namespace edgewise::test {

const FastInterpolation* fast_interpolation(Isa isa) {
  switch (isa) {
#define EDGEWISE_TEST_TABLE_CASE(name, arch, cpu_check) \
  case Isa::name:                                       \
    return &isa_test_##name::fast_interpolation();
    EDGEWISE_FOR_EACH_SIMD_ISA(EDGEWISE_TEST_TABLE_CASE)
#undef EDGEWISE_TEST_TABLE_CASE
    default:
      return nullptr;
  }
}

}  // namespace edgewise::test
