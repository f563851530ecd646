#include "coverage_result.hpp"

#include <algorithm>
#include <bit>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace edgewise::test {
namespace {

class CollectingSink final : public CoverageSink {
 public:
  explicit CollectingSink(std::vector<TileCoverage>& tiles) : tiles_(tiles) {}
  void consume(std::span<const TileCoverage> tiles) override {
    tiles_.insert(tiles_.end(), tiles.begin(), tiles.end());
  }

 private:
  std::vector<TileCoverage>& tiles_;
};

bool same_tile(const TileCoverage& a, const TileCoverage& b) {
  return a.triangle == b.triangle && a.tile_x == b.tile_x && a.tile_y == b.tile_y &&
         a.mask == b.mask && a.sample == b.sample;
}

void append_pixels(const TileCoverage& tile, std::vector<Pixel>& out) {
  for (std::uint64_t mask = tile.mask; mask != 0; mask &= mask - 1) {
    const int bit = std::countr_zero(mask);
    out.push_back(
        {tile.tile_x * kTileSize + bit % kTileSize, tile.tile_y * kTileSize + bit / kTileSize});
  }
}

std::string format_mask(std::uint64_t mask) {
  char text[32];
  std::snprintf(text, sizeof text, "0x%016" PRIx64, mask);
  return text;
}

std::string format_status(TriangleStatus status) {
  return std::string(describe(status));
}

// Tiles of one triangle, keyed by (tile_y, tile_x).
std::map<std::pair<int, int>, std::uint64_t> tiles_of(const RasterRun& run,
                                                      std::uint32_t triangle) {
  std::map<std::pair<int, int>, std::uint64_t> tiles;
  for (const TileCoverage& tile : run.tiles) {
    if (tile.triangle == triangle) tiles[{tile.tile_y, tile.tile_x}] |= tile.mask;
  }
  return tiles;
}

// The first tile and pixel where two triangles' coverage differs, in words.
std::string first_tile_difference(const RasterRun& expected, const RasterRun& actual,
                                  std::uint32_t triangle) {
  const auto want = tiles_of(expected, triangle);
  const auto got = tiles_of(actual, triangle);
  std::map<std::pair<int, int>, std::pair<std::uint64_t, std::uint64_t>> both;
  for (const auto& [key, mask] : want)
    both[key].first = mask;
  for (const auto& [key, mask] : got)
    both[key].second = mask;
  for (const auto& [key, masks] : both) {
    if (masks.first == masks.second) continue;
    const std::uint64_t diff = masks.first ^ masks.second;
    const int bit = std::countr_zero(diff);
    const int px = key.second * kTileSize + bit % kTileSize;
    const int py = key.first * kTileSize + bit / kTileSize;
    std::ostringstream out;
    out << "first differing tile (" << key.second << ", " << key.first << "): expected mask "
        << format_mask(masks.first) << ", actual " << format_mask(masks.second)
        << "; first differing pixel (" << px << ", " << py << ") with sample (" << px << ".5, "
        << py << ".5): expected " << ((masks.first >> bit) & 1 ? "covered" : "not covered")
        << ", actual " << ((masks.second >> bit) & 1 ? "covered" : "not covered");
    return out.str();
  }
  return "same masks, different tile order or batching";
}

bool same_tiles_of(const RasterRun& a, const RasterRun& b, std::uint32_t triangle) {
  std::vector<TileCoverage> ta, tb;
  for (const TileCoverage& t : a.tiles)
    if (t.triangle == triangle) ta.push_back(t);
  for (const TileCoverage& t : b.tiles)
    if (t.triangle == triangle) tb.push_back(t);
  return std::equal(ta.begin(), ta.end(), tb.begin(), tb.end(), same_tile);
}

std::string describe_report(const RasterReport& r) {
  std::ostringstream out;
  out << "triangles " << r.triangles << ", drawn " << r.drawn << ", culled " << r.culled
      << ", errors " << r.errors;
  if (r.first_error_triangle) {
    out << ", first error at triangle " << *r.first_error_triangle << " ("
        << describe(r.first_error) << ")";
  }
  return out.str();
}

bool same_counts(const RasterReport& a, const RasterReport& b) {
  return a.triangles == b.triangles && a.drawn == b.drawn && a.culled == b.culled &&
         a.errors == b.errors && a.first_error_triangle == b.first_error_triangle &&
         (!a.first_error_triangle || a.first_error == b.first_error);
}

}  // namespace

RasterRun run_raster(Isa isa, const RasterCall& call) {
  RasterRun run;
  run.statuses.assign(call.triangle_count(), TriangleStatus::drawn);
  RasterOptions options;
  options.cull = call.cull;
  options.isa = isa;
  options.statuses = run.statuses;
  options.samples = call.samples;
  CollectingSink sink(run.tiles);
  run.report = rasterize(call.vertices, call.indices, call.target, options, sink);
  return run;
}

std::vector<Pixel> covered_pixels(const RasterRun& run) {
  std::vector<Pixel> pixels;
  for (const TileCoverage& tile : run.tiles)
    append_pixels(tile, pixels);
  std::sort(pixels.begin(), pixels.end());
  return pixels;
}

std::vector<Pixel> covered_pixels(const RasterRun& run, std::uint32_t triangle) {
  std::vector<Pixel> pixels;
  for (const TileCoverage& tile : run.tiles) {
    if (tile.triangle == triangle) append_pixels(tile, pixels);
  }
  std::sort(pixels.begin(), pixels.end());
  return pixels;
}

std::string format_pixels(std::span<const Pixel> pixels) {
  std::ostringstream out;
  out << pixels.size() << " pixels:";
  for (const Pixel& p : pixels)
    out << " (" << p.x << "," << p.y << ")";
  return out.str();
}

std::string format_float(float v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.9g (%a)", static_cast<double>(v), static_cast<double>(v));
  return text;
}

std::string describe_triangle(const RasterCall& call, std::size_t triangle) {
  std::ostringstream out;
  out << "triangle " << triangle << ":";
  for (int corner = 0; corner < 3; ++corner) {
    const std::size_t slot = 3 * triangle + corner;
    std::size_t index = slot;
    if (!call.indices.empty()) index = call.indices[slot];
    out << "\n  v" << corner;
    if (!call.indices.empty()) out << " [index " << index << "]";
    if (index < call.vertices.size()) {
      out << " x = " << format_float(call.vertices[index].x)
          << ", y = " << format_float(call.vertices[index].y);
    } else {
      out << " past the end of " << call.vertices.size() << " vertices";
    }
  }
  return out.str();
}

std::string describe_call(const RasterCall& call) {
  std::ostringstream out;
  out << "target " << call.target.width << "x" << call.target.height;
  if (call.target.scissor) {
    const PixelRect& s = *call.target.scissor;
    out << ", scissor [" << s.x0 << ", " << s.x1 << ") x [" << s.y0 << ", " << s.y1 << ")";
  }
  const char* cull_names[] = {"none", "clockwise", "counter_clockwise"};
  out << ", cull " << cull_names[static_cast<int>(call.cull)] << ", " << call.triangle_count()
      << " triangles" << (call.indices.empty() ? "" : " (indexed)");
  return out.str();
}

::testing::AssertionResult well_formed(const RasterCall& call, const RasterRun& run) {
  const PixelRect clip = clip_rect(call.target);
  const TileCoverage* previous = nullptr;
  for (const TileCoverage& tile : run.tiles) {
    std::ostringstream where;
    where << "tile (" << tile.tile_x << ", " << tile.tile_y << ") of triangle " << tile.triangle
          << " [" << describe_call(call) << "]";
    if (tile.mask == 0) return ::testing::AssertionFailure() << "empty mask in " << where.str();
    if (tile.triangle >= call.triangle_count()) {
      return ::testing::AssertionFailure() << "no such triangle: " << where.str();
    }
    if (run.statuses[tile.triangle] != TriangleStatus::drawn) {
      return ::testing::AssertionFailure()
             << "coverage from a triangle that was not drawn ("
             << describe(run.statuses[tile.triangle]) << "): " << where.str();
    }
    std::vector<Pixel> pixels;
    append_pixels(tile, pixels);
    for (const Pixel& p : pixels) {
      if (p.x < clip.x0 || p.x >= clip.x1 || p.y < clip.y0 || p.y >= clip.y1) {
        return ::testing::AssertionFailure()
               << "pixel (" << p.x << ", " << p.y << ") outside the clip rectangle in "
               << where.str() << "\n"
               << describe_triangle(call, tile.triangle);
      }
    }
    if (previous != nullptr) {
      const auto order = [](const TileCoverage& t) {
        return std::tuple(t.triangle, t.tile_y, t.tile_x, t.sample);
      };
      if (!(order(*previous) < order(tile))) {
        return ::testing::AssertionFailure()
               << "tiles out of order (triangle, then tile_y, tile_x and sample): " << where.str()
               << " after tile (" << previous->tile_x << ", " << previous->tile_y
               << ") of triangle " << previous->triangle;
      }
    }
    previous = &tile;
  }
  RasterReport counted;
  counted.triangles = run.statuses.size();
  for (std::size_t t = 0; t < run.statuses.size(); ++t) {
    const TriangleStatus status = run.statuses[t];
    if (status == TriangleStatus::drawn) {
      ++counted.drawn;
    } else if (is_error(status)) {
      if (counted.errors++ == 0) {
        counted.first_error_triangle = t;
        counted.first_error = status;
      }
    } else {
      ++counted.culled;
    }
  }
  if (!same_counts(counted, run.report)) {
    return ::testing::AssertionFailure()
           << "report (" << describe_report(run.report) << ") disagrees with the statuses ("
           << describe_report(counted) << ")";
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult same_coverage(const RasterCall& call, const RasterRun& expected,
                                         const RasterRun& actual) {
  const bool tiles_equal = std::equal(expected.tiles.begin(), expected.tiles.end(),
                                      actual.tiles.begin(), actual.tiles.end(), same_tile);
  if (tiles_equal && expected.statuses == actual.statuses &&
      same_counts(expected.report, actual.report)) {
    return ::testing::AssertionSuccess();
  }
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  failure << name_of(actual.report.isa) << " differs from " << name_of(expected.report.isa) << " ["
          << describe_call(call) << "]";
  for (std::uint32_t t = 0; t < call.triangle_count(); ++t) {
    const bool status_differs = expected.statuses[t] != actual.statuses[t];
    if (!status_differs && same_tiles_of(expected, actual, t)) continue;
    failure << "\n" << describe_triangle(call, t);
    if (status_differs) {
      failure << "\n  status: expected " << format_status(expected.statuses[t]) << ", actual "
              << format_status(actual.statuses[t]);
    }
    failure << "\n  " << first_tile_difference(expected, actual, t) << "\n  expected "
            << format_pixels(covered_pixels(expected, t)).substr(0, 2000) << "\n  actual   "
            << format_pixels(covered_pixels(actual, t)).substr(0, 2000);
    return failure;
  }
  if (!tiles_equal) return failure << "\nsame tiles per triangle, but in a different order";
  return failure << "\nreports differ: expected " << describe_report(expected.report) << "; actual "
                 << describe_report(actual.report);
}

RasterRun run_checked(Isa isa, const RasterCall& call) {
  RasterRun run = run_raster(isa, call);
  EXPECT_EQ(run.report.isa, isa);
  EXPECT_TRUE(well_formed(call, run));
  if (isa != Isa::reference) {
    EXPECT_TRUE(same_coverage(call, run_raster(Isa::reference, call), run));
  }
  return run;
}

RasterRun draw(Isa isa, std::span<const Vec2> vertices, const RasterTarget& target, CullMode cull) {
  return run_checked(isa, RasterCall{vertices, {}, target, cull});
}

std::vector<std::vector<Vec2>> vertex_orders(const Vec2& a, const Vec2& b, const Vec2& c) {
  return {{a, b, c}, {b, c, a}, {c, a, b}, {a, c, b}, {c, b, a}, {b, a, c}};
}

}  // namespace edgewise::test
