// EDGEWISE_ISA, run as its own process per value (tests/CMakeLists.txt sets the variable), since
// the library reads the environment once: a supported name is the ISA that runs; an unknown or
// unsupported one makes default-ISA calls throw std::invalid_argument with a message naming the
// value and the ISAs this machine supports; an empty one means the best ISA.
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/edgewise.hpp"

namespace edgewise {
namespace {

class NullSink final : public CoverageSink {
 public:
  void consume(std::span<const TileCoverage>) override {}
};

const std::vector<Vec2> kTriangle = {{0.5f, 0.5f}, {12.0f, 1.0f}, {3.0f, 9.0f}};
const RasterTarget kTarget{16, 16, {}};

TEST(IsaEnvironment, NamedIsaRunsOrIsRejected) {
  const char* value = std::getenv("EDGEWISE_ISA");
  if (value == nullptr) GTEST_SKIP() << "run with EDGEWISE_ISA set (ctest sets it)";
  const std::optional<Isa> named = *value == '\0' ? best_isa() : parse_name<Isa>(value);
  NullSink sink;

  if (named && isa_supported(*named)) {
    EXPECT_EQ(active_isa(), *named);
    EXPECT_EQ(rasterize(kTriangle, {}, kTarget, {}, sink).isa, *named);
    EXPECT_EQ(count_coverage(kTriangle, {}, kTarget, {}).report.isa, *named);
  } else {
    try {
      active_isa();
      ADD_FAILURE() << "EDGEWISE_ISA=" << value << " was accepted";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("EDGEWISE_ISA=" + std::string(value)), std::string::npos) << message;
      EXPECT_NE(message.find(named ? "not supported" : "unknown"), std::string::npos) << message;
      for (Isa isa : supported_isas()) {
        EXPECT_NE(message.find(name_of(isa)), std::string::npos) << message;
      }
    }
    EXPECT_THROW(rasterize(kTriangle, {}, kTarget, {}, sink), std::invalid_argument);
    EXPECT_THROW(count_coverage(kTriangle, {}, kTarget, {}), std::invalid_argument);
  }

  // An explicit choice needs no environment and wins over it.
  RasterOptions options;
  options.isa = Isa::reference;
  EXPECT_EQ(rasterize(kTriangle, {}, kTarget, options, sink).isa, Isa::reference);
  const ScopedIsa scoped(Isa::reference);
  EXPECT_EQ(active_isa(), Isa::reference);
}

}  // namespace
}  // namespace edgewise
