// edgewise-coverage: lists the pixels each triangle covers as runs per row, so that edgewise can
// be diffed against any other rasterizer, and its fast paths against the reference.
#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <utility>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/input_file.hpp"
#include "common/isa_options.hpp"
#include "common/option_values.hpp"
#include "common/output_file.hpp"
#include "common/run_tool.hpp"
#include "common/usage_error.hpp"
#include "common/value_options.hpp"
#include "edgewise/edgewise.hpp"

namespace {

using namespace edgewise;

constexpr const char* kDescription =
    "TRIANGLES has one triangle per line, 'x0 y0 x1 y1 x2 y2' in pixels (origin top-left, y down,\n"
    "pixel centers at +0.5); '#' starts a comment; '-' reads standard input. For each triangle\n"
    "prints '<index> <pixel_count> <row>:<first_col>-<last_col> ...': inclusive runs of covered\n"
    "pixels, rows ascending. Culled and invalid triangles print '<index> 0' and are reported on\n"
    "standard error.\n"
    "--samples N (2, 4, 8 or 16) decides the standard multisample pattern's samples instead of\n"
    "pixel centres and prints '<index> <pixel_count> <x>:<y>:<mask> ...' per triangle: the pixels\n"
    "with a covered sample, row by row, each with its samples in hex (bit k for sample k).\n"
    "--area prints '<index> <pixel_count> <x>:<y>:<area> ...' per triangle: the area of each "
    "pixel\n"
    "the triangle covers in part, in square pixels (9 significant digits), row by row; pixels\n"
    "of zero area are left out. With --compare-isas, areas may differ from the reference's by the\n"
    "stated tolerance (1e-6).\n"
    "--compare-isas rasterizes with the reference and every ISA this CPU supports and exits with\n"
    "status 1 if any output differs from the reference's.";

// Bad input: the message names what was wrong and where.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// W or H: an integer in 0..kMaxTargetSize.
tools::Option add_dimension(tools::CommandLine& command_line, const std::string& name,
                            const std::string& what, std::int32_t& value) {
  return tools::add_parsed_option(
             command_line, name, value,
             [what](const std::string& text) {
               return static_cast<std::int32_t>(tools::integer_in(what, text, 0, kMaxTargetSize));
             },
             "the target's " + what + " in pixels, 0.." + std::to_string(kMaxTargetSize))
      .type_name("")
      .required();
}

// A float as written, or nullopt. NaN and infinity are accepted: they are valid input that the
// rasterizer reports as a triangle error.
std::optional<float> parse_coordinate(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  const char* first = text.data();
  const char* last = first + text.size();
  float value = 0.0f;
  auto [end, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) {
    // Subnormal results count as out of range for from_chars; they are fine coordinates.
    double wide = 0.0;
    const auto [wide_end, wide_ec] = std::from_chars(first, last, wide);
    if (wide_ec != std::errc() || std::abs(wide) > std::numeric_limits<float>::max()) {
      return std::nullopt;
    }
    value = static_cast<float>(wide);
    end = wide_end;
    ec = std::errc();
  }
  if (ec != std::errc() || end != last) return std::nullopt;
  return value;
}

// Three vertices per triangle, in input order.
// A triangle's line is short; a longer one is not this format (a binary file, /dev/zero on
// standard input), refused before it fills memory.
constexpr std::size_t kMaxLineLength = 4096;

// The next line of `in` without its newline, into `line`; false at the end of the input. Throws
// InputError for a line longer than kMaxLineLength.
bool read_line(std::istream& in, std::string& line, const std::string& where) {
  line.clear();
  std::streambuf& buffer = *in.rdbuf();
  for (auto c = buffer.sbumpc(); c != std::char_traits<char>::eof(); c = buffer.sbumpc()) {
    if (c == '\n') return true;
    if (line.size() == kMaxLineLength) {
      throw InputError(where + "a line longer than " + std::to_string(kMaxLineLength) +
                       " characters: not a list of triangles");
    }
    line.push_back(static_cast<char>(c));
  }
  return !line.empty();
}

std::vector<Vec2> read_triangles(std::istream& in, const std::string& name) {
  std::vector<Vec2> vertices;
  std::string line;
  for (std::size_t line_number = 1;
       read_line(in, line, name + ":" + std::to_string(line_number) + ": "); ++line_number) {
    std::string_view rest(line);
    rest = rest.substr(0, rest.find('#'));
    const auto where = [&] { return name + ":" + std::to_string(line_number) + ": "; };
    std::vector<std::string_view> fields;
    constexpr std::string_view kSpace = " \t\r\f\v";
    while (true) {
      const std::size_t begin = rest.find_first_not_of(kSpace);
      if (begin == std::string_view::npos) break;
      rest.remove_prefix(begin);
      const std::size_t end = std::min(rest.find_first_of(kSpace), rest.size());
      fields.push_back(rest.substr(0, end));
      rest.remove_prefix(end);
    }
    if (fields.empty()) continue;
    if (fields.size() != 6) {
      throw InputError(where() + "expected 6 numbers 'x0 y0 x1 y1 x2 y2', found " +
                       std::to_string(fields.size()) + " fields");
    }
    float xy[6];
    for (std::size_t i = 0; i < 6; ++i) {
      const std::optional<float> value = parse_coordinate(fields[i]);
      if (!value) {
        throw InputError(where() + "'" + std::string(fields[i]) +
                         "' is not a number in the float range");
      }
      xy[i] = *value;
    }
    vertices.insert(vertices.end(), {{xy[0], xy[1]}, {xy[2], xy[3]}, {xy[4], xy[5]}});
  }
  if (in.bad()) throw InputError(name + ": read error: " + std::strerror(errno));
  return vertices;
}

// Keeps every tile a sink of masks (CoverageSink) or of areas (AreaSink) is handed.
template <class Sink, class Tile>
class Collector final : public Sink {
 public:
  void consume(std::span<const Tile> tiles) override {
    tiles_.insert(tiles_.end(), tiles.begin(), tiles.end());
  }
  std::vector<Tile>& tiles() { return tiles_; }

 private:
  std::vector<Tile> tiles_;
};
using TileCollector = Collector<CoverageSink, TileCoverage>;
using AreaCollector = Collector<AreaSink, AreaTile>;

// The end of the tile row that starts at tiles[begin] (tiles sorted by tile row).
template <class Tile>
std::size_t tile_row_end(std::span<const Tile> tiles, std::size_t begin) {
  std::size_t end = begin;
  while (end < tiles.size() && tiles[end].tile_y == tiles[begin].tile_y)
    ++end;
  return end;
}

// Appends ' <row>:<first>-<last>' (huge triangles have thousands of runs: no temporaries).
void append_run(std::string& out, std::uint32_t row, std::uint32_t first, std::uint32_t last) {
  const auto append_number = [&out](std::uint32_t value) {
    char digits[std::numeric_limits<std::uint32_t>::digits10 + 1];
    out.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
  };
  out += ' ';
  append_number(row);
  out += ':';
  append_number(first);
  out += '-';
  append_number(last);
}

// '<pixel_count> <row>:<first>-<last> ...' for one triangle's tiles, which must be sorted by
// tile row, then tile column.
std::string format_runs(std::span<const TileCoverage> tiles, std::uint64_t& pixel_count) {
  std::string runs;
  pixel_count = 0;
  for (std::size_t row_begin = 0; row_begin < tiles.size();) {
    const std::size_t row_end = tile_row_end(tiles, row_begin);
    for (int y = 0; y < kTileSize; ++y) {
      const std::uint32_t row = std::uint32_t{tiles[row_begin].tile_y} * kTileSize + y;
      std::optional<std::uint32_t> first, last;
      const auto flush = [&] {
        if (!first) return;
        append_run(runs, row, *first, *last);
        pixel_count += *last - *first + 1;
        first.reset();
      };
      for (std::size_t t = row_begin; t < row_end; ++t) {
        std::uint32_t bits = (tiles[t].mask >> (y * kTileSize)) & 0xffu;
        while (bits != 0) {
          const int start = std::countr_zero(bits);
          const int length = std::countr_one(bits >> start);
          const std::uint32_t col = std::uint32_t{tiles[t].tile_x} * kTileSize + start;
          if (!first || col != *last + 1) {
            flush();
            first = col;
          }
          last = col + length - 1;
          bits &= ~(((1u << length) - 1u) << start);
        }
      }
      flush();
    }
    row_begin = row_end;
  }
  return std::to_string(pixel_count) + runs;
}

// '<pixel_count> <x>:<y>:<mask> ...' for one triangle's tiles of every sample, which must be
// sorted by tile row, then tile column: each pixel with a covered sample and its sample mask.
std::string format_sample_masks(std::span<const TileCoverage> tiles, std::uint64_t& pixel_count) {
  std::string pixels;
  pixel_count = 0;
  for (std::size_t row_begin = 0; row_begin < tiles.size();) {
    const std::size_t row_end = tile_row_end(tiles, row_begin);
    for (int y = 0; y < kTileSize; ++y) {
      for (std::size_t t = row_begin; t < row_end;) {
        // The tile's records, one per sample with a covered sample.
        std::size_t tile_end = t;
        while (tile_end < row_end && tiles[tile_end].tile_x == tiles[t].tile_x)
          ++tile_end;
        for (int x = 0; x < kTileSize; ++x) {
          const int bit = y * kTileSize + x;
          std::uint32_t mask = 0;
          for (std::size_t r = t; r < tile_end; ++r)
            mask |= static_cast<std::uint32_t>((tiles[r].mask >> bit) & 1u) << tiles[r].sample;
          if (mask == 0) continue;
          char text[64];
          const int length = std::snprintf(text, sizeof text, " %u:%u:%x",
                                           std::uint32_t{tiles[t].tile_x} * kTileSize + x,
                                           std::uint32_t{tiles[t].tile_y} * kTileSize + y, mask);
          pixels.append(text, static_cast<std::size_t>(length));
          ++pixel_count;
        }
        t = tile_end;
      }
    }
    row_begin = row_end;
  }
  return std::to_string(pixel_count) + pixels;
}

// Calls pixel(x, y, area) for each pixel of a triangle's area tiles (in row order), row by row.
template <class Pixel>
void for_each_area_pixel(std::span<const AreaTile> tiles, Pixel&& pixel) {
  for (std::size_t row_begin = 0; row_begin < tiles.size();) {
    const std::size_t row_end = tile_row_end(tiles, row_begin);
    for (int y = 0; y < kTileSize; ++y) {
      for (std::size_t t = row_begin; t < row_end; ++t) {
        for (int x = 0; x < kTileSize; ++x) {
          const int bit = y * kTileSize + x;
          if ((tiles[t].mask >> bit & 1u) == 0) continue;
          pixel(std::uint32_t{tiles[t].tile_x} * kTileSize + x,
                std::uint32_t{tiles[t].tile_y} * kTileSize + y, tiles[t].area[bit]);
        }
      }
    }
    row_begin = row_end;
  }
}

// '<pixel_count> <x>:<y>:<area> ...' for one triangle's area tiles.
std::string format_areas(std::span<const AreaTile> tiles, std::uint64_t& pixel_count) {
  std::string pixels;
  pixel_count = 0;
  for_each_area_pixel(tiles, [&](std::uint32_t x, std::uint32_t y, float area) {
    char text[64];
    const int length =
        std::snprintf(text, sizeof text, " %u:%u:%.9g", x, y, static_cast<double>(area));
    pixels.append(text, static_cast<std::size_t>(length));
    ++pixel_count;
  });
  return std::to_string(pixel_count) + pixels;
}

// Each triangle's area tiles for triangles [first, first + count) with one ISA; statuses too.
std::vector<std::vector<AreaTile>> areas_of(std::span<const Vec2> vertices, std::size_t first,
                                            std::size_t count, const RasterTarget& target, Isa isa,
                                            std::vector<TriangleStatus>& statuses) {
  statuses.assign(count, TriangleStatus::drawn);
  RasterOptions options;
  options.isa = isa;
  options.statuses = statuses;
  AreaCollector collector;
  rasterize_areas(vertices.subspan(3 * first, 3 * count), {}, target, options, collector);
  std::vector<std::vector<AreaTile>> per_triangle(count);
  for (const AreaTile& tile : collector.tiles())
    per_triangle[tile.triangle].push_back(tile);
  return per_triangle;
}

struct TriangleCoverage {
  std::size_t index;
  TriangleStatus status;
  std::string line;  // the output line without its newline
};

// Rasterizes triangles [first, first + count) of `vertices` with one ISA.
std::vector<TriangleCoverage> cover(std::span<const Vec2> vertices, std::size_t first,
                                    std::size_t count, const RasterTarget& target, int samples,
                                    Isa isa, std::uint64_t& pixels) {
  std::vector<TriangleStatus> statuses(count);
  RasterOptions options;
  options.isa = isa;
  options.statuses = statuses;
  options.samples = samples;
  TileCollector collector;
  rasterize(vertices.subspan(3 * first, 3 * count), {}, target, options, collector);

  std::vector<TileCoverage>& tiles = collector.tiles();
  std::stable_sort(tiles.begin(), tiles.end(), [](const TileCoverage& a, const TileCoverage& b) {
    if (a.triangle != b.triangle) return a.triangle < b.triangle;
    if (a.tile_y != b.tile_y) return a.tile_y < b.tile_y;
    return a.tile_x < b.tile_x;
  });
  std::vector<TriangleCoverage> result(count);
  std::size_t next_tile = 0;
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t begin = next_tile;
    while (next_tile < tiles.size() && tiles[next_tile].triangle == t)
      ++next_tile;
    std::uint64_t triangle_pixels = 0;
    const std::span<const TileCoverage> triangle_tiles =
        std::span(tiles).subspan(begin, next_tile - begin);
    const std::string runs = samples > 1 ? format_sample_masks(triangle_tiles, triangle_pixels)
                                         : format_runs(triangle_tiles, triangle_pixels);
    pixels += triangle_pixels;
    result[t] = {first + t, statuses[t], std::to_string(first + t) + ' ' + runs};
  }
  return result;
}

// Bounds memory for large inputs: tiles are kept for one chunk of triangles at a time.
constexpr std::size_t kChunkTriangles = 256;

void list_coverage(std::span<const Vec2> vertices, const RasterTarget& target, int samples, Isa isa,
                   std::ostream& out) {
  const std::size_t triangles = vertices.size() / 3;
  std::uint64_t pixels = 0;
  for (std::size_t first = 0; first < triangles; first += kChunkTriangles) {
    const std::size_t count = std::min(kChunkTriangles, triangles - first);
    if (samples == 0) {  // --area
      std::vector<TriangleStatus> statuses;
      const auto areas = areas_of(vertices, first, count, target, isa, statuses);
      for (std::size_t t = 0; t < count; ++t) {
        std::uint64_t triangle_pixels = 0;
        out << first + t << ' ' << format_areas(areas[t], triangle_pixels) << '\n';
        if (statuses[t] != TriangleStatus::drawn) {
          std::cerr << "triangle " << first + t << ": " << describe(statuses[t]) << '\n';
        }
      }
      continue;
    }
    for (const TriangleCoverage& c : cover(vertices, first, count, target, samples, isa, pixels)) {
      out << c.line << '\n';
      if (c.status != TriangleStatus::drawn) {
        std::cerr << "triangle " << c.index << ": " << describe(c.status) << '\n';
      }
    }
  }
}

// Returns whether every supported ISA reproduces the reference's output exactly.
bool compare_isas(std::span<const Vec2> vertices, const RasterTarget& target, int samples) {
  const std::size_t triangles = vertices.size() / 3;
  bool all_equal = true;
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;
    std::uint64_t pixels = 0, reference_pixels = 0;
    std::size_t mismatches = 0;
    for (std::size_t first = 0; first < triangles; first += kChunkTriangles) {
      const std::size_t count = std::min(kChunkTriangles, triangles - first);
      const auto expected =
          cover(vertices, first, count, target, samples, Isa::reference, reference_pixels);
      const auto actual = cover(vertices, first, count, target, samples, isa, pixels);
      for (std::size_t t = 0; t < count; ++t) {
        if (expected[t].status == actual[t].status && expected[t].line == actual[t].line) continue;
        if (mismatches++ == 0) {
          const Vec2* v = &vertices[3 * (first + t)];
          std::cout << std::setprecision(9)  // enough digits to read back the same floats
                    << name_of(isa) << ": differs from the reference on triangle " << first + t
                    << " (" << v[0].x << ' ' << v[0].y << ' ' << v[1].x << ' ' << v[1].y << ' '
                    << v[2].x << ' ' << v[2].y << ")\n  reference: " << expected[t].line << " ["
                    << describe(expected[t].status) << "]\n  " << name_of(isa) << ": "
                    << actual[t].line << " [" << describe(actual[t].status) << "]\n";
        }
      }
    }
    if (mismatches == 0) {
      std::cout << name_of(isa) << ": identical to the reference on " << triangles << " triangles ("
                << pixels
                << (samples > 1 ? " pixels with a covered sample)\n" : " covered pixels)\n");
    } else {
      std::cout << name_of(isa) << ": " << mismatches << " of " << triangles
                << " triangles differ from the reference\n";
      all_equal = false;
    }
  }
  return all_equal;
}

// Whether every supported ISA's areas lie within the tolerance of the reference's (which is
// within 2^-44 of exact), pixel by pixel, with the same statuses.
bool compare_isas_areas(std::span<const Vec2> vertices, const RasterTarget& target) {
  const std::size_t triangles = vertices.size() / 3;
  const double tolerance = kPixelAreaTolerance + 0x1p-44;
  bool all_close = true;
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;
    std::size_t mismatches = 0;
    double worst = 0.0;
    std::uint64_t pixels = 0;
    for (std::size_t first = 0; first < triangles; first += kChunkTriangles) {
      const std::size_t count = std::min(kChunkTriangles, triangles - first);
      std::vector<TriangleStatus> expected_statuses, actual_statuses;
      const auto expected =
          areas_of(vertices, first, count, target, Isa::reference, expected_statuses);
      const auto actual = areas_of(vertices, first, count, target, isa, actual_statuses);
      for (std::size_t t = 0; t < count; ++t) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<double, double>> both;
        for_each_area_pixel(expected[t], [&](std::uint32_t x, std::uint32_t y, float area) {
          both[{y, x}].first = area;
        });
        for_each_area_pixel(actual[t], [&](std::uint32_t x, std::uint32_t y, float area) {
          both[{y, x}].second = area;
        });
        double largest = 0.0;
        for (const auto& [pixel, areas] : both)
          largest = std::max(largest, std::abs(areas.first - areas.second));
        pixels += both.size();
        worst = std::max(worst, largest);
        if (largest <= tolerance && expected_statuses[t] == actual_statuses[t]) continue;
        if (mismatches++ == 0) {
          const Vec2* v = &vertices[3 * (first + t)];
          std::cout << std::setprecision(9) << name_of(isa)
                    << ": differs from the reference by more than the tolerance on triangle "
                    << first + t << " (" << v[0].x << ' ' << v[0].y << ' ' << v[1].x << ' '
                    << v[1].y << ' ' << v[2].x << ' ' << v[2].y << "): by " << largest << " ["
                    << describe(expected_statuses[t]) << " / " << describe(actual_statuses[t])
                    << "]\n";
        }
      }
    }
    if (mismatches == 0) {
      std::cout << name_of(isa) << ": within " << kPixelAreaTolerance << " of the reference on "
                << triangles << " triangles (" << pixels << " pixels, largest difference " << worst
                << ")\n";
    } else {
      std::cout << name_of(isa) << ": " << mismatches << " of " << triangles
                << " triangles differ from the reference\n";
      all_close = false;
    }
  }
  return all_close;
}

struct Arguments {
  RasterTarget target;
  std::string triangles;
  std::optional<Isa> isa;
  std::optional<std::string> output;
  bool compare = false;
  int samples = 1;
  bool area = false;
};

void add_options(tools::CommandLine& command_line, Arguments& arguments) {
  command_line.description(kDescription);
  add_dimension(command_line, "W", "width", arguments.target.width);
  add_dimension(command_line, "H", "height", arguments.target.height);
  tools::add_text_option(command_line, "TRIANGLES", arguments.triangles,
                         "the triangles' file, '-' for standard input")
      .type_name("")
      .required();
  tools::add_isa_options(command_line, arguments.isa,
                         "the ISA to rasterize with (default: the best ISA of this CPU, or "
                         "EDGEWISE_ISA)",
                         "rasterize with the scalar reference");
  tools::add_text_option(command_line, "-o", arguments.output, "write the output to FILE")
      .type_name("FILE");
  command_line.add_flag("--compare-isas", arguments.compare,
                        "compare every supported ISA with the reference");
  tools::add_parsed_option(
      command_line, "--samples", arguments.samples,
      [](const std::string& text) {
        const auto samples = static_cast<int>(tools::integer_in("--samples", text, 1, 16));
        if (!is_standard_sample_count(samples)) {
          throw tools::UsageError("--samples: " + text +
                                  " has no standard pattern (1, 2, 4, 8 or 16)");
        }
        return samples;
      },
      "samples per pixel: 1 (the pixel centre, the default), 2, 4, 8 or 16 (the standard "
      "multisample patterns)")
      .type_name("N");
  command_line.add_flag(
      "--area", arguments.area,
      "print each pixel's exact area inside the triangle instead of covered samples");
}

int run(const Arguments& arguments) {
  if (arguments.compare && (arguments.isa || arguments.output)) {
    throw tools::UsageError("--compare-isas takes no --isa, --reference or -o");
  }
  std::vector<Vec2> vertices;
  if (arguments.triangles == "-") {
    vertices = read_triangles(std::cin, "<stdin>");
  } else {
    tools::require_regular_file(arguments.triangles);
    std::ifstream file(arguments.triangles);
    if (!file) {
      throw InputError(arguments.triangles + ": cannot open: " + std::strerror(errno));
    }
    vertices = read_triangles(file, arguments.triangles);
  }

  if (arguments.area && arguments.samples > 1) {
    throw tools::UsageError("--area takes no --samples");
  }
  if (arguments.compare && arguments.area) {
    return compare_isas_areas(vertices, arguments.target) ? 0 : 1;
  }
  if (arguments.compare) return compare_isas(vertices, arguments.target, arguments.samples) ? 0 : 1;

  const Isa isa = tools::tool_isa(arguments.isa);
  if (!arguments.output) {
    list_coverage(vertices, arguments.target, arguments.area ? 0 : arguments.samples, isa,
                  std::cout);
    std::cout.flush();
    if (!std::cout) throw InputError("cannot write to standard output");
    return 0;
  }
  tools::OutputStream out(*arguments.output);
  list_coverage(vertices, arguments.target, arguments.area ? 0 : arguments.samples, isa, out);
  out.finish();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  return tools::run_tool(
      argc, argv, "edgewise-coverage",
      {"W H TRIANGLES [--samples N | --area] [--isa NAME | --reference] [-o FILE]",
       "W H TRIANGLES [--samples N | --area] --compare-isas"},
      [&arguments](tools::CommandLine& command_line) {
        add_options(command_line, arguments);
        return [&arguments] { return run(arguments); };
      });
}
