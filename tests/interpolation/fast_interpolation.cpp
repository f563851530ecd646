#include "fast_interpolation.hpp"

namespace edgewise {
#if defined(__x86_64__)
namespace isa_test_sse2 {
const test::FastInterpolation& fast_interpolation();
}
namespace isa_test_sse4_1 {
const test::FastInterpolation& fast_interpolation();
}
namespace isa_test_avx2 {
const test::FastInterpolation& fast_interpolation();
}
#elif defined(__aarch64__)
namespace isa_test_neon {
const test::FastInterpolation& fast_interpolation();
}
#endif

namespace test {

const FastInterpolation* fast_interpolation(Isa isa) {
  switch (isa) {
#if defined(__x86_64__)
    case Isa::sse2:
      return &isa_test_sse2::fast_interpolation();
    case Isa::sse4_1:
      return &isa_test_sse4_1::fast_interpolation();
    case Isa::avx2:
      return &isa_test_avx2::fast_interpolation();
#elif defined(__aarch64__)
    case Isa::neon:
      return &isa_test_neon::fast_interpolation();
#endif
    default:
      return nullptr;
  }
}

}  // namespace test
}  // namespace edgewise
