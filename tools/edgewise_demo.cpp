// edgewise-demo: renders a 2D test pattern of a few thousand triangles to a PNG, checks that every
// ISA covers it exactly like the reference, and prints per-ISA coverage throughput.
//
// The pattern is chosen to show the fill rule: a jittered grid and a star-shaped fan whose
// triangles share edges (every sample covered exactly once), slivers thinner than a pixel, and
// sub-pixel triangles. Two magnified insets show the pixels around the fan's center, where 72
// triangles meet on one sample, and a corner of the grid, with the true edges drawn over them.
#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <random>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/image_file.hpp"
#include "common/isa_options.hpp"
#include "common/median.hpp"
#include "common/run_tool.hpp"
#include "edgewise/edgewise.hpp"
#include "exact_area_triangles.hpp"

namespace {

using namespace edgewise;

// ---- The pattern ----------------------------------------------------------------------------

constexpr int kPatternWidth = 1280, kPatternHeight = 720;

struct Group {
  std::string name;
  std::size_t first = 0, count = 0;  // triangle range
};

struct Pattern {
  std::vector<Vec2> vertices;  // three per triangle
  std::vector<Group> groups;
  std::size_t triangles() const { return vertices.size() / 3; }
  void begin_group(std::string name) { groups.push_back({std::move(name), triangles(), 0}); }
  // Appends a triangle to the last group.
  void add(Vec2 a, Vec2 b, Vec2 c) {
    vertices.insert(vertices.end(), {a, b, c});
    ++groups.back().count;
  }
};

// Cells of the jittered grid; its outer border stays on whole pixels so that the samples inside
// it are exactly those of a rectangle.
constexpr int kGridX0 = 16, kGridY0 = 16, kGridCell = 16, kGridColumns = 36, kGridRows = 43;
constexpr int kGridX1 = kGridX0 + kGridColumns * kGridCell;
constexpr int kGridY1 = kGridY0 + kGridRows * kGridCell;
constexpr PixelRect kGridRect{kGridX0, kGridY0, kGridX1, kGridY1};
// The fan's center is a pixel center: every one of its triangles has a vertex on that sample.
constexpr Vec2 kFanCenter{800.5f, 240.5f};
constexpr int kFanSpokes = 72;

void add_jittered_grid(Pattern& pattern, std::mt19937& rng) {
  pattern.begin_group("jittered grid");
  // Below a quarter cell (rounding included) every quad stays convex, so neither diagonal split
  // folds over: the triangles tile the rectangle.
  std::uniform_real_distribution<float> jitter(-3.5f, 3.5f);
  std::uniform_int_distribution<int> coin(0, 2);
  std::vector<Vec2> points((kGridColumns + 1) * (kGridRows + 1));
  for (int j = 0; j <= kGridRows; ++j) {
    for (int i = 0; i <= kGridColumns; ++i) {
      Vec2 p{float(kGridX0 + i * kGridCell), float(kGridY0 + j * kGridCell)};
      const bool border_x = i == 0 || i == kGridColumns, border_y = j == 0 || j == kGridRows;
      if (!border_x) p.x += jitter(rng);
      if (!border_y) p.y += jitter(rng);
      // A third of the vertices sit on multiples of half a pixel: edges through samples.
      if (coin(rng) == 0) p = {std::round(p.x * 2) / 2, std::round(p.y * 2) / 2};
      points[j * (kGridColumns + 1) + i] = p;
    }
  }
  for (int j = 0; j < kGridRows; ++j) {
    for (int i = 0; i < kGridColumns; ++i) {
      const Vec2 a = points[j * (kGridColumns + 1) + i], b = points[j * (kGridColumns + 1) + i + 1];
      const Vec2 c = points[(j + 1) * (kGridColumns + 1) + i];
      const Vec2 d = points[(j + 1) * (kGridColumns + 1) + i + 1];
      if (coin(rng) == 0) {  // either diagonal; both windings occur
        pattern.add(a, b, d);
        pattern.add(a, d, c);
      } else {
        pattern.add(a, b, c);
        pattern.add(c, b, d);
      }
    }
  }
}

void add_star_fan(Pattern& pattern) {
  pattern.begin_group("star fan");
  constexpr double kOuter = 200.0, kInner = 120.0, kTurn = 0.1;  // px, px, rad
  auto rim = [&](int k) {
    const double angle = kTurn + 2.0 * std::numbers::pi * k / kFanSpokes;
    const double radius = k % 2 == 0 ? kOuter : kInner;
    return Vec2{float(kFanCenter.x + radius * std::cos(angle)),
                float(kFanCenter.y + radius * std::sin(angle))};
  };
  for (int k = 0; k < kFanSpokes; ++k)
    pattern.add(kFanCenter, rim(k), rim(k + 1));
}

void add_slivers(Pattern& pattern, std::mt19937& rng) {
  pattern.begin_group("slivers");
  constexpr float kX0 = 620, kX1 = 1260, kY0 = 470, kY1 = 710;
  std::uniform_real_distribution<float> x(kX0, kX1), y(kY0, kY1), width(0.05f, 1.5f);
  for (int n = 0; n < 160; ++n) {
    const Vec2 a{x(rng), y(rng)}, b{x(rng), y(rng)};
    const float dx = b.x - a.x, dy = b.y - a.y, length = std::max(1.0f, std::hypot(dx, dy));
    const float w = width(rng);
    pattern.add(a, b, {b.x - w * dy / length, b.y + w * dx / length});
  }
}

void add_tiny(Pattern& pattern, std::mt19937& rng) {
  pattern.begin_group("tiny");
  std::uniform_real_distribution<float> x(1040, 1260), y(20, 450), offset(-1.6f, 1.6f);
  for (int n = 0; n < 3000; ++n) {
    const Vec2 c{x(rng), y(rng)};
    auto near = [&] { return Vec2{c.x + offset(rng), c.y + offset(rng)}; };
    pattern.add(near(), near(), near());
  }
}

// make_pattern() adds the two meshes first, in this order.
constexpr std::size_t kGridGroup = 0, kFanGroup = 1;

Pattern make_pattern() {
  std::mt19937 rng(2024);
  Pattern pattern;
  add_jittered_grid(pattern, rng);
  add_star_fan(pattern);
  add_slivers(pattern, rng);
  add_tiny(pattern, rng);
  return pattern;
}

// ---- Coverage of the pattern ------------------------------------------------------------------

class TileRecorder final : public CoverageSink {
 public:
  void consume(std::span<const TileCoverage> tiles) override {
    tiles_.insert(tiles_.end(), tiles.begin(), tiles.end());
  }
  const std::vector<TileCoverage>& tiles() const { return tiles_; }

 private:
  std::vector<TileCoverage> tiles_;
};

std::vector<TileCoverage> cover(const Pattern& pattern, Isa isa) {
  RasterOptions options;
  options.isa = isa;
  TileRecorder recorder;
  const RasterReport report =
      rasterize(pattern.vertices, {}, {kPatternWidth, kPatternHeight, {}}, options, recorder);
  if (report.errors != 0) throw std::logic_error("the demo pattern has invalid triangles");
  return recorder.tiles();
}

bool same_tiles(std::span<const TileCoverage> a, std::span<const TileCoverage> b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const TileCoverage& x, const TileCoverage& y) {
                      return x.triangle == y.triangle && x.tile_x == y.tile_x &&
                             x.tile_y == y.tile_y && x.mask == y.mask;
                    });
}

template <class PixelFn>
void for_each_pixel(const TileCoverage& tile, PixelFn&& fn) {
  for (std::uint64_t bits = tile.mask; bits != 0; bits &= bits - 1) {
    const int bit = std::countr_zero(bits);
    fn(int(tile.tile_x) * kTileSize + bit % kTileSize,
       int(tile.tile_y) * kTileSize + bit / kTileSize);
  }
}

std::uint64_t covered_pixels(std::span<const TileCoverage> tiles) {
  std::uint64_t pixels = 0;
  for (const TileCoverage& tile : tiles)
    pixels += std::popcount(tile.mask);
  return pixels;
}

struct Watertightness {
  std::uint64_t samples = 0, gaps = 0, overlaps = 0;
};

// How often each sample of `region` is covered by the group's triangles: a mesh that shares its
// edges covers the samples inside it exactly once.
Watertightness check_group(std::span<const TileCoverage> tiles, const Group& group,
                           const PixelRect& region, bool expect_full) {
  const int width = region.x1 - region.x0, height = region.y1 - region.y0;
  std::vector<std::uint8_t> count(std::size_t(width) * height, 0);
  for (const TileCoverage& tile : tiles) {
    if (tile.triangle < group.first || tile.triangle >= group.first + group.count) continue;
    for_each_pixel(tile, [&](int x, int y) {
      if (x < region.x0 || x >= region.x1 || y < region.y0 || y >= region.y1) return;
      std::uint8_t& c = count[std::size_t(y - region.y0) * width + (x - region.x0)];
      c = std::uint8_t(std::min(c + 1, 2));
    });
  }
  Watertightness w;
  w.samples = count.size();
  for (std::uint8_t c : count) {
    w.gaps += expect_full && c == 0;
    w.overlaps += c > 1;
  }
  return w;
}

// ---- The image --------------------------------------------------------------------------------

using Rgb = std::array<std::uint8_t, 3>;

class Image {
 public:
  Image(int width, int height, Rgb fill)
      : width_(width), height_(height), pixels_(std::size_t(width) * height * 3) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x)
        set(x, y, fill);
    }
  }
  int width() const { return width_; }
  int height() const { return height_; }
  Rgb get(int x, int y) const {
    const std::uint8_t* p = &pixels_[(std::size_t(y) * width_ + x) * 3];
    return {p[0], p[1], p[2]};
  }
  void set(int x, int y, Rgb c) {
    std::uint8_t* p = &pixels_[(std::size_t(y) * width_ + x) * 3];
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
  }
  void write_png(const std::string& path) const {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    tools::ImagePixels image;
    image.width = width_;
    image.height = height_;
    image.channels = 3;
    image.bytes = pixels_;
    tools::write_image_file(path, image);
  }

 private:
  int width_, height_;
  std::vector<std::uint8_t> pixels_;
};

// Neighbouring triangles get well separated hues (golden-ratio steps around the color wheel).
Rgb triangle_color(std::uint32_t triangle) {
  const double hue = std::fmod(triangle * 0.6180339887498949, 1.0) * 6.0;
  const double saturation = 0.45 + 0.3 * ((triangle * 7919u) % 5) / 4.0;
  const double value = 0.7 + 0.3 * ((triangle * 104729u) % 3) / 2.0;
  const int sector = int(hue);
  const double f = hue - sector;
  const double p = value * (1 - saturation), q = value * (1 - saturation * f),
               t = value * (1 - saturation * (1 - f));
  double r = value, g = t, b = p;
  switch (sector % 6) {
    case 1:
      r = q, g = value, b = p;
      break;
    case 2:
      r = p, g = value, b = t;
      break;
    case 3:
      r = p, g = q, b = value;
      break;
    case 4:
      r = t, g = p, b = value;
      break;
    case 5:
      r = value, g = p, b = q;
      break;
    default:
      break;
  }
  return {std::uint8_t(255 * r), std::uint8_t(255 * g), std::uint8_t(255 * b)};
}

constexpr Rgb kBackground{21, 21, 24}, kOverlap{255, 0, 0}, kGap{255, 255, 255};

// Covered pixels in their triangle's color; samples of the grid and the fan covered twice in
// red, samples of the grid left uncovered in white (neither should ever be seen).
Image paint(const Pattern& pattern, std::span<const TileCoverage> tiles) {
  Image image(kPatternWidth, kPatternHeight, kBackground);
  std::vector<std::uint8_t> mesh_count(std::size_t(kPatternWidth) * kPatternHeight, 0);
  const std::size_t mesh_end = pattern.groups[kFanGroup].first + pattern.groups[kFanGroup].count;
  for (const TileCoverage& tile : tiles) {
    const Rgb color = triangle_color(tile.triangle);
    const bool in_mesh = tile.triangle < mesh_end;  // the grid and the fan come first
    for_each_pixel(tile, [&](int x, int y) {
      std::uint8_t& c = mesh_count[std::size_t(y) * kPatternWidth + x];
      if (in_mesh) c = std::uint8_t(std::min(c + 1, 2));
      image.set(x, y, in_mesh && c > 1 ? kOverlap : color);
    });
  }
  for (int y = kGridRect.y0; y < kGridRect.y1; ++y) {
    for (int x = kGridRect.x0; x < kGridRect.x1; ++x) {
      if (mesh_count[std::size_t(y) * kPatternWidth + x] == 0) image.set(x, y, kGap);
    }
  }
  return image;
}

double distance_to_segment(double px, double py, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  const double t =
      length2 > 0 ? std::clamp(((px - a.x) * dx + (py - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(px - (a.x + t * dx), py - (a.y + t * dy));
}

// Copies source pixels [x0, x0 + size) x [y0, y0 + size) magnified `zoom` times to (left, top),
// with a dark line between pixels, a dot on each sample and the triangles' true edges in white.
void draw_inset(Image& out, const Image& source, const Pattern& pattern, int x0, int y0, int size,
                int zoom, int left, int top) {
  std::vector<std::array<Vec2, 2>> edges;
  for (std::size_t t = 0; t < pattern.triangles(); ++t) {
    const Vec2* v = &pattern.vertices[3 * t];
    const auto [min_x, max_x] = std::minmax({v[0].x, v[1].x, v[2].x});
    const auto [min_y, max_y] = std::minmax({v[0].y, v[1].y, v[2].y});
    if (max_x < x0 || min_x > x0 + size || max_y < y0 || min_y > y0 + size) continue;
    for (int e = 0; e < 3; ++e)
      edges.push_back({v[e], v[(e + 1) % 3]});
  }
  const double half_line = 0.6 / zoom;  // in source pixels: lines about one pixel wide
  for (int v = 0; v < size * zoom; ++v) {
    for (int u = 0; u < size * zoom; ++u) {
      const int sx = x0 + u / zoom, sy = y0 + v / zoom;
      Rgb c = source.get(sx, sy);
      const int cx = u % zoom, cy = v % zoom;
      if (cx == 0 || cy == 0) c = {0, 0, 0};
      if ((cx == zoom / 2 || cx == zoom / 2 - 1) && (cy == zoom / 2 || cy == zoom / 2 - 1)) {
        c = {0, 0, 0};
      }
      const double px = x0 + (u + 0.5) / zoom, py = y0 + (v + 0.5) / zoom;
      for (const auto& edge : edges) {
        if (distance_to_segment(px, py, edge[0], edge[1]) < half_line) {
          c = {255, 255, 255};
          break;
        }
      }
      out.set(left + u, top + v, c);
    }
  }
}

Image compose(const Pattern& pattern, const Image& rendered) {
  constexpr int kInsetSource = 26, kZoom = 12, kMargin = 16;
  constexpr int kInsetSize = kInsetSource * kZoom;
  Image image(kPatternWidth + kInsetSize + kMargin, kPatternHeight, kBackground);
  for (int y = 0; y < kPatternHeight; ++y) {
    for (int x = 0; x < kPatternWidth; ++x)
      image.set(x, y, rendered.get(x, y));
  }
  const int left = kPatternWidth;
  draw_inset(image, rendered, pattern, int(kFanCenter.x) - kInsetSource / 2,
             int(kFanCenter.y) - kInsetSource / 2, kInsetSource, kZoom, left, kMargin);
  draw_inset(image, rendered, pattern, kGridRect.x0 - 4, kGridRect.y0 - 4, kInsetSource, kZoom,
             left, 2 * kMargin + kInsetSize);
  return image;
}

// ---- Throughput -------------------------------------------------------------------------------

struct Throughput {
  double triangles_per_second = 0, pixels_per_second = 0;
};

Throughput measure(std::span<const Vec2> vertices, Isa isa, int runs) {
  const RasterTarget target{1920, 1080, {}};
  RasterOptions options;
  options.isa = isa;
  const std::uint64_t pixels = count_coverage(vertices, {}, target, options).pixels;  // warm-up
  std::vector<double> seconds;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const CoverageCount count = count_coverage(vertices, {}, target, options);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (count.pixels != pixels) throw std::logic_error("coverage count changed between runs");
  }
  const double median = tools::median(seconds);
  return {double(vertices.size() / 3) / median, double(pixels) / median};
}

std::string si(double value) {
  std::ostringstream s;
  s << std::setprecision(3);
  if (value >= 1e9) {
    s << value / 1e9 << " G";
  } else if (value >= 1e6) {
    s << value / 1e6 << " M";
  } else if (value >= 1e3) {
    s << value / 1e3 << " k";
  } else {
    s << value << " ";
  }
  return s.str();
}

void print_throughput(std::span<const Isa> isas) {
  struct Workload {
    int area;
    std::size_t triangles;  // the reference takes about 50-100 ms per run
  };
  constexpr Workload kWorkloads[] = {{8, 100000}, {64, 50000}, {1000, 4000}, {200000, 32}};
  constexpr int kRuns = 5;
  std::cout << "\nthroughput: count_coverage() of random triangles on 1920x1080, one call per "
               "run, median of "
            << kRuns << " runs\n";
  std::cout << std::left << std::setw(8) << "area" << std::setw(11) << "ISA" << std::setw(15)
            << "triangles/s" << std::setw(14) << "pixels/s"
            << "vs reference\n";
  for (const Workload& w : kWorkloads) {
    const std::vector<Vec2> vertices =
        workload::exact_area_triangles(w.triangles, w.area, 1920, 1080, 0xdeadbeef + w.area);
    double reference_rate = 0;
    for (Isa isa : isas) {
      const Throughput t = measure(vertices, isa, kRuns);
      if (isa == Isa::reference) reference_rate = t.triangles_per_second;
      std::ostringstream ratio;
      ratio << std::fixed << std::setprecision(1) << t.triangles_per_second / reference_rate << "x";
      std::cout << std::setw(8) << w.area << std::setw(11) << name_of(isa) << std::setw(15)
                << si(t.triangles_per_second) + "/s" << std::setw(14)
                << si(t.pixels_per_second) + "/s" << (reference_rate > 0 ? ratio.str() : "-")
                << '\n';
    }
  }
}

// ---- Main -------------------------------------------------------------------------------------

int run(const std::string& output) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Isa> isas = supported_isas();
  const Isa active = tools::tool_isa(std::nullopt);
  std::cout << "edgewise-demo: active ISA " << name_of(active) << " (supported:";
  for (Isa isa : isas)
    std::cout << ' ' << name_of(isa);
  std::cout << ")\n";

  const Pattern pattern = make_pattern();
  std::cout << "pattern: " << pattern.triangles() << " triangles on " << kPatternWidth << "x"
            << kPatternHeight << " (";
  for (const Group& g : pattern.groups) {
    std::cout << g.name << ' ' << g.count << (&g == &pattern.groups.back() ? ")\n" : ", ");
  }

  // Pixel-exact check: every ISA must deliver the reference's tile masks bit for bit.
  bool ok = true;
  const std::vector<TileCoverage> reference = cover(pattern, Isa::reference);
  std::vector<TileCoverage> shown = reference;
  std::cout << "coverage of the pattern vs the reference (every tile mask, bit for bit):\n";
  for (Isa isa : isas) {
    const std::vector<TileCoverage> tiles = cover(pattern, isa);
    const bool same = same_tiles(tiles, reference);
    ok = ok && same;
    std::cout << "  " << std::left << std::setw(10) << name_of(isa)
              << (isa == Isa::reference ? "is the reference"
                  : same                ? "identical"
                                        : "DIFFERENT")
              << " (" << tiles.size() << " tiles, " << covered_pixels(tiles) << " pixels)\n";
    if (isa == active) shown = tiles;
  }

  const Watertightness grid = check_group(shown, pattern.groups[kGridGroup], kGridRect, true);
  const PixelRect fan_box{int(kFanCenter.x) - 210, int(kFanCenter.y) - 210, int(kFanCenter.x) + 210,
                          int(kFanCenter.y) + 210};
  const Watertightness fan = check_group(shown, pattern.groups[kFanGroup], fan_box, false);
  std::cout << "watertight: jittered grid " << grid.gaps << " gaps, " << grid.overlaps
            << " overlaps in " << grid.samples << " samples; star fan " << fan.overlaps
            << " overlaps\n";
  ok = ok && grid.gaps == 0 && grid.overlaps == 0 && fan.overlaps == 0;

  compose(pattern, paint(pattern, shown)).write_png(output);
  std::cout << "wrote " << output << " (rendered with " << name_of(active) << ")\n";

  print_throughput(isas);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "\n"
            << (ok ? "all checks passed" : "CHECKS FAILED") << " in " << std::fixed
            << std::setprecision(1) << elapsed << " s\n";
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string output = "out/edgewise-demo.png";
  return tools::run_tool(
      argc, argv, "edgewise-demo", {"[-o FILE.png]"}, [&output](tools::CommandLine& command_line) {
        command_line.description(
            "Renders a 2D test pattern to a PNG, checks that every ISA covers it exactly like the\n"
            "reference, and prints per-ISA coverage throughput.");
        tools::add_text_option(command_line, "-o", output,
                               "the PNG to write (default out/edgewise-demo.png)")
            .type_name("FILE.png");
        return [&output] { return run(output); };
      });
}
