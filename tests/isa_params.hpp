// One GoogleTest parameter per compiled ISA, the ISA's name in the test name
// (`Raster.TopLeftRule/avx2`). An ISA this CPU cannot run is skipped, visibly, rather than left
// out, so a report shows which paths were not exercised.
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "edgewise/isa.hpp"

namespace edgewise {
// GoogleTest prints parameters and values through PrintTo found by argument-dependent lookup.
inline void PrintTo(Isa isa, std::ostream* out) {
  *out << name_of(isa);
}
}  // namespace edgewise

namespace edgewise::test {

class IsaTest : public ::testing::TestWithParam<Isa> {
 protected:
  void SetUp() override {
    if (!isa_supported(GetParam())) {
      GTEST_SKIP() << name_of(GetParam()) << " is compiled in but this CPU cannot run it";
    }
  }
  Isa isa() const { return GetParam(); }
};

inline std::string isa_test_name(const ::testing::TestParamInfo<Isa>& info) {
  return std::string(name_of(info.param));
}

// Every value of the Isa enum, compiled here or not (name_of() names each of them).
inline std::vector<Isa> every_isa_value() {
  std::vector<Isa> isas;
  for (int i = 0; name_of(static_cast<Isa>(i)) != "unknown"; ++i)
    isas.push_back(static_cast<Isa>(i));
  return isas;
}

// Every compiled ISA, the scalar reference included.
inline std::vector<Isa> every_isa() {
  return {compiled_isas().begin(), compiled_isas().end()};
}

// The compiled fast paths: what is compared against the reference.
inline std::vector<Isa> fast_isas() {
  std::vector<Isa> isas;
  for (Isa isa : compiled_isas()) {
    if (isa != Isa::reference) isas.push_back(isa);
  }
  return isas;
}

}  // namespace edgewise::test

// Instantiates `suite` (a TEST_P suite deriving from IsaTest) once per ISA of `isa_list`.
#define EDGEWISE_INSTANTIATE_PER_ISA(suite, isa_list) \
  INSTANTIATE_TEST_SUITE_P(, suite, ::testing::ValuesIn(isa_list), ::edgewise::test::isa_test_name)
