// Rasterizes a 10 x 10 pixel square made of two triangles through the installed package, on every
// ISA this CPU supports. The diagonal they share passes exactly through ten pixel centers; the
// top-left rule gives each of those to one triangle, so exactly 100 pixels are covered.
#include <bit>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include <edgewise/edgewise.hpp>

namespace {

// Counts covered pixels and how many pixels were delivered twice.
class CountingSink : public edgewise::CoverageSink {
 public:
  void consume(std::span<const edgewise::TileCoverage> tiles) override {
    for (const edgewise::TileCoverage& tile : tiles) {
      std::uint64_t& seen = seen_[tile.tile_y * kTilesPerRow + tile.tile_x];
      pixels += std::popcount(tile.mask);
      overlaps += std::popcount(seen & tile.mask);
      seen |= tile.mask;
    }
  }
  std::uint64_t pixels = 0;
  std::uint64_t overlaps = 0;

 private:
  static constexpr int kTilesPerRow = 4;
  std::uint64_t seen_[kTilesPerRow * kTilesPerRow] = {};
};

}  // namespace

int main() {
  const std::vector<edgewise::Vec2> corners = {{3, 3}, {13, 3}, {13, 13}, {3, 13}};
  const std::vector<std::uint32_t> triangles = {0, 1, 2, 0, 2, 3};
  edgewise::RasterTarget target;
  target.width = 32;
  target.height = 32;
  constexpr std::uint64_t kExpected = 100;

  int failures = 0;
  for (edgewise::Isa isa : edgewise::supported_isas()) {
    CountingSink sink;
    edgewise::RasterOptions options;
    options.isa = isa;
    const edgewise::RasterReport report =
        edgewise::rasterize(corners, triangles, target, options, sink);
    const bool ok =
        sink.pixels == kExpected && sink.overlaps == 0 && report.drawn == 2 && report.isa == isa;
    std::printf("%-9s %llu pixels, %llu covered twice, ran on %s: %s\n",
                std::string(edgewise::name_of(isa)).c_str(),
                static_cast<unsigned long long>(sink.pixels),
                static_cast<unsigned long long>(sink.overlaps),
                std::string(edgewise::name_of(report.isa)).c_str(), ok ? "ok" : "WRONG");
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? 0 : 1;
}
