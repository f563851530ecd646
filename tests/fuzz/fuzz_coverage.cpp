// Differential fuzz target: the input bytes become a target, a scissor, a cull mode and a
// batch of triangles; every supported ISA and the scalar reference rasterize it, and any
// difference in tiles, statuses, report counts or pixel counts prints every ISA's output side
// by side and aborts. Exact areas (rasterize_areas()) are compared too: every ISA's within the
// tolerance of the reference's at every pixel.
//
// Input layout (missing bytes read as zero):
//   u16 width, u16 height        target size, each modulo 32769
//   u16 x, u16 y, u8 w, u8 h     scissor window (always within 64 px per side, so the reference
//                                stays fast even on a 32768 x 32768 target)
//   u8 flags                     bits 0-1: cull mode (3 = none); bit 2: indexed; bits 3-5:
//                                samples per pixel, 1 << (value % 5) (1, 2, 4, 8 or 16)
//   then per triangle (at most 32):
//     u8 modes                   two bits per vertex: how its coordinates are encoded
//     3 x (u32 x, u32 y)         0, 1: near the window, 1/65536 px resolution (ties, samples);
//                                2: signed 16.16 px over the whole guard band; 3: raw float bits
//                                (NaN, infinities, denormals, huge values)
//   indexed batches then read one u8 per corner: an index modulo (vertex count + 2), so some
//   indices are past the end.
#include <algorithm>
#include <bit>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <map>
#include <tuple>
#include <span>
#include <string>
#include <vector>

#include "edgewise/edgewise.hpp"

namespace {

using namespace edgewise;

constexpr std::size_t kMaxTriangles = 32;
constexpr std::int32_t kMaxWindow = 64;

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  bool empty() const { return pos_ >= bytes_.size(); }
  std::uint32_t read(int count) {
    std::uint32_t value = 0;
    for (int i = 0; i < count; ++i) {
      const std::uint32_t byte = pos_ < bytes_.size() ? bytes_[pos_] : 0;
      ++pos_;
      value |= byte << (8 * i);
    }
    return value;
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

float decode_coordinate(std::uint32_t bits, int mode, std::int32_t window_origin) {
  switch (mode) {
    case 0:
    case 1:  // the window's corner plus a signed 8.16 px offset: +-128 px in 1/65536 px
      return static_cast<float>(
          window_origin + static_cast<double>(static_cast<std::int32_t>(bits) >> 8) / 65536.0);
    case 2:  // anywhere in (and just at the ends of) the guard band
      return static_cast<float>(static_cast<double>(static_cast<std::int32_t>(bits)) / 65536.0);
    default:
      return std::bit_cast<float>(bits);
  }
}

class CollectingSink final : public CoverageSink {
 public:
  void consume(std::span<const TileCoverage> batch) override {
    tiles.insert(tiles.end(), batch.begin(), batch.end());
  }
  std::vector<TileCoverage> tiles;
};

struct Output {
  Isa isa;
  RasterReport report;
  std::vector<TriangleStatus> statuses;
  std::vector<TileCoverage> tiles;
  std::uint64_t counted_pixels = 0;  // from count_coverage()
};

bool same(const Output& a, const Output& b) {
  const auto same_tile = [](const TileCoverage& x, const TileCoverage& y) {
    return x.triangle == y.triangle && x.tile_x == y.tile_x && x.tile_y == y.tile_y &&
           x.mask == y.mask && x.sample == y.sample;
  };
  return a.statuses == b.statuses &&
         std::equal(a.tiles.begin(), a.tiles.end(), b.tiles.begin(), b.tiles.end(), same_tile) &&
         a.report.triangles == b.report.triangles && a.report.drawn == b.report.drawn &&
         a.report.culled == b.report.culled && a.report.errors == b.report.errors &&
         a.report.first_error_triangle == b.report.first_error_triangle &&
         a.counted_pixels == b.counted_pixels;
}

std::uint64_t popcount_of(const std::vector<TileCoverage>& tiles) {
  std::uint64_t pixels = 0;
  for (const TileCoverage& t : tiles)
    pixels += static_cast<std::uint64_t>(std::popcount(t.mask));
  return pixels;
}

[[noreturn]] void report_mismatch(std::span<const Vec2> vertices,
                                  std::span<const std::uint32_t> indices,
                                  const RasterTarget& target, CullMode cull, int samples,
                                  std::span<const Output> outputs) {
  std::fprintf(stderr, "edgewise: ISA outputs differ\ntarget %dx%d", target.width, target.height);
  if (target.scissor) {
    std::fprintf(stderr, ", scissor [%d, %d) x [%d, %d)", target.scissor->x0, target.scissor->x1,
                 target.scissor->y0, target.scissor->y1);
  }
  std::fprintf(stderr, ", cull %d, %s, %d sample(s) per pixel\n", static_cast<int>(cull),
               indices.empty() ? "unindexed" : "indexed", samples);
  const std::size_t triangles = outputs.front().statuses.size();
  for (std::size_t t = 0; t < triangles; ++t) {
    std::fprintf(stderr, "triangle %zu:", t);
    for (int c = 0; c < 3; ++c) {
      const std::size_t index = indices.empty() ? 3 * t + c : indices[3 * t + c];
      if (index >= vertices.size()) {
        std::fprintf(stderr, "  [index %zu: past the end]", index);
        continue;
      }
      std::fprintf(stderr, "  (%.9g, %.9g) = (%a, %a)", static_cast<double>(vertices[index].x),
                   static_cast<double>(vertices[index].y), static_cast<double>(vertices[index].x),
                   static_cast<double>(vertices[index].y));
    }
    std::fprintf(stderr, "\n");
  }
  std::fprintf(stderr, "%-10s %9s %6s %6s %6s %8s %12s\n", "isa", "triangles", "drawn", "culled",
               "errors", "tiles", "pixels");
  for (const Output& o : outputs) {
    std::fprintf(stderr,
                 "%-10s %9" PRIu64 " %6" PRIu64 " %6" PRIu64 " %6" PRIu64 " %8zu %6" PRIu64
                 "/%-6" PRIu64 "\n",
                 std::string(name_of(o.isa)).c_str(), o.report.triangles, o.report.drawn,
                 o.report.culled, o.report.errors, o.tiles.size(), popcount_of(o.tiles),
                 o.counted_pixels);
  }
  std::fprintf(stderr, "statuses:\n");
  for (std::size_t t = 0; t < triangles; ++t) {
    std::fprintf(stderr, "  triangle %zu:", t);
    for (const Output& o : outputs)
      std::fprintf(stderr, " %s=%d", std::string(name_of(o.isa)).c_str(),
                   static_cast<int>(o.statuses[t]));
    std::fprintf(stderr, "\n");
  }
  std::fprintf(stderr, "tiles (triangle, tile_x, tile_y, sample: mask per ISA):\n");
  std::size_t longest = 0;
  for (const Output& o : outputs)
    longest = std::max(longest, o.tiles.size());
  for (std::size_t i = 0; i < longest; ++i) {
    for (const Output& o : outputs) {
      if (i < o.tiles.size()) {
        const TileCoverage& t = o.tiles[i];
        std::fprintf(stderr, "  %3u %5u %5u %2u %016" PRIx64, t.triangle, t.tile_x, t.tile_y,
                     static_cast<unsigned>(t.sample), t.mask);
      } else {
        std::fprintf(stderr, "  %36s", "-");
      }
    }
    std::fprintf(stderr, "\n");
  }
  std::abort();
}

class AreaCollector final : public AreaSink {
 public:
  void consume(std::span<const AreaTile> batch) override {
    tiles.insert(tiles.end(), batch.begin(), batch.end());
  }
  std::vector<AreaTile> tiles;
};

// Each pixel's area, keyed by (triangle, y, x).
std::map<std::tuple<std::uint32_t, std::int32_t, std::int32_t>, double> areas_of(
    Isa isa, std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
    const RasterTarget& target, CullMode cull) {
  RasterOptions options;
  options.cull = cull;
  options.isa = isa;
  AreaCollector sink;
  rasterize_areas(vertices, indices, target, options, sink);
  std::map<std::tuple<std::uint32_t, std::int32_t, std::int32_t>, double> areas;
  for (const AreaTile& tile : sink.tiles) {
    for (int bit = 0; bit < 64; ++bit) {
      if ((tile.mask >> bit & 1u) == 0) continue;
      areas[{tile.triangle, tile.tile_y * 8 + bit / 8, tile.tile_x * 8 + bit % 8}] = tile.area[bit];
    }
  }
  return areas;
}

// Aborts when an ISA's area of some pixel is off the reference's by more than the tolerance.
void compare_areas(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                   const RasterTarget& target, CullMode cull) {
  const auto expected = areas_of(Isa::reference, vertices, indices, target, cull);
  const double tolerance = kPixelAreaTolerance + 0x1p-44;
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;
    auto actual = areas_of(isa, vertices, indices, target, cull);
    for (const auto& [pixel, area] : expected)
      actual.try_emplace(pixel, 0.0);
    for (const auto& [pixel, area] : actual) {
      const auto found = expected.find(pixel);
      const double want = found == expected.end() ? 0.0 : found->second;
      if (std::abs(area - want) <= tolerance) continue;
      std::fprintf(stderr,
                   "edgewise: %s's area of pixel (%d, %d) of triangle %u is %.9g, the "
                   "reference's %.9g\n",
                   std::string(name_of(isa)).c_str(), std::get<2>(pixel), std::get<1>(pixel),
                   std::get<0>(pixel), area, want);
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in({data, size});
  RasterTarget target;
  target.width = static_cast<std::int32_t>(in.read(2) % (kMaxTargetSize + 1));
  target.height = static_cast<std::int32_t>(in.read(2) % (kMaxTargetSize + 1));
  PixelRect window;
  window.x0 = static_cast<std::int32_t>(in.read(2) % (target.width + 1));
  window.y0 = static_cast<std::int32_t>(in.read(2) % (target.height + 1));
  window.x1 = window.x0 + static_cast<std::int32_t>(in.read(1) % (kMaxWindow + 1));
  window.y1 = window.y0 + static_cast<std::int32_t>(in.read(1) % (kMaxWindow + 1));
  target.scissor = window;
  const std::uint32_t flags = in.read(1);
  const CullMode cull = (flags & 3) == 3 ? CullMode::none : static_cast<CullMode>(flags & 3);
  const bool indexed = (flags & 4) != 0;
  const int samples = 1 << (((flags >> 3) & 7) % 5);

  std::vector<Vec2> vertices;
  while (!in.empty() && vertices.size() < 3 * kMaxTriangles) {
    const std::uint32_t modes = in.read(1);
    for (int corner = 0; corner < 3; ++corner) {
      const int mode = static_cast<int>((modes >> (2 * corner)) & 3);
      const float x = decode_coordinate(in.read(4), mode, window.x0);
      const float y = decode_coordinate(in.read(4), mode, window.y0);
      vertices.push_back({x, y});
    }
  }
  std::vector<std::uint32_t> indices;
  if (indexed) {
    for (std::size_t i = 0; i < vertices.size(); ++i)
      indices.push_back(in.read(1) % static_cast<std::uint32_t>(vertices.size() + 2));
  }

  std::vector<Output> outputs;
  for (Isa isa : supported_isas()) {
    Output out{isa, {}, std::vector<TriangleStatus>(vertices.size() / 3), {}, 0};
    RasterOptions options;
    options.cull = cull;
    options.isa = isa;
    options.statuses = out.statuses;
    options.samples = samples;
    CollectingSink sink;
    out.report = rasterize(vertices, indices, target, options, sink);
    out.tiles = std::move(sink.tiles);
    options.statuses = {};
    out.counted_pixels = count_coverage(vertices, indices, target, options).pixels;
    if (out.report.isa != isa || out.counted_pixels != popcount_of(out.tiles)) {
      outputs.push_back(std::move(out));
      report_mismatch(vertices, indices, target, cull, samples, outputs);
    }
    outputs.push_back(std::move(out));
  }
  // supported_isas() lists the reference first.
  for (const Output& out : outputs) {
    if (!same(outputs.front(), out)) {
      report_mismatch(vertices, indices, target, cull, samples, outputs);
    }
  }
  compare_areas(vertices, indices, target, cull);
  return 0;
}
