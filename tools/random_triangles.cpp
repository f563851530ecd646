// edgewise-random-triangles: writes random triangles in edgewise-coverage's input format, drawn
// from generators that aim at the hard cases (ties, slivers, tiny and huge triangles, invalid
// vertices), for diffing ISAs against the reference or edgewise against another rasterizer.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/option_values.hpp"
#include "common/output_file.hpp"
#include "common/run_tool.hpp"
#include "common/value_options.hpp"
#include "edgewise/coverage.hpp"
#include "exact_area_triangles.hpp"

namespace {

using edgewise::Vec2;

constexpr const char* kDescription =
    "Writes COUNT triangles 'x0 y0 x1 y1 x2 y2' around a W x H target, cycling through the\n"
    "generators uniform, tiny, sliver, ties, near-axis, exact-area, huge and degenerate.";

struct Triangle {
  Vec2 v[3];
};

class Generators {
 public:
  Generators(int width, int height, std::uint64_t seed)
      : width_(width), height_(height), rng_(seed) {}

  Triangle next(std::size_t index) {
    switch (index % 8) {
      case 0:
        return uniform();
      case 1:
        return tiny();
      case 2:
        return sliver();
      case 3:
        return ties();
      case 4:
        return near_axis();
      case 5:
        return exact_area();
      case 6:
        return huge();
      default:
        return degenerate();
    }
  }

 private:
  double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  Vec2 point(double margin) {
    return {float(real(-margin * width_, (1 + margin) * width_)),
            float(real(-margin * height_, (1 + margin) * height_))};
  }

  // Anywhere on the target, reaching a little past its borders.
  Triangle uniform() { return {{point(0.25), point(0.25), point(0.25)}}; }

  // Sub-pixel to a few pixels: most cover zero to a handful of samples.
  Triangle tiny() {
    const Vec2 c = point(0.0);
    const double r = real(0.05, 3.0);
    auto near = [&] { return Vec2{float(c.x + real(-r, r)), float(c.y + real(-r, r))}; };
    return {{near(), near(), near()}};
  }

  // Long and thinner than a pixel.
  Triangle sliver() {
    const Vec2 a = point(0.1), b = point(0.1);
    const double t = real(0.0, 1.0), offset = real(-0.3, 0.3);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double length = std::max(1e-3, std::hypot(dx, dy));
    const Vec2 c{float(a.x + t * dx - offset * dy / length),
                 float(a.y + t * dy + offset * dx / length)};
    return {{a, b, c}};
  }

  // Vertices on pixel centers and borders (multiples of 1/2) and on snapping ties (odd multiples
  // of 1/512): samples land exactly on edges, and rounding to 1/256 must tie to even.
  Triangle ties() {
    const bool snap_ties = integer(0, 1) == 1;
    const int denominator = snap_ties ? 512 : 2;
    auto coordinate = [&](int size) {
      int k = integer(-denominator, (size + 1) * denominator);
      if (snap_ties) k |= 1;
      return float(double(k) / denominator);
    };
    auto vertex = [&] { return Vec2{coordinate(width_), coordinate(height_)}; };
    return {{vertex(), vertex(), vertex()}};
  }

  // One edge almost or exactly horizontal or vertical.
  Triangle near_axis() {
    const Vec2 a = point(0.1);
    const double along = real(-0.6, 0.6) * std::max(width_, height_);
    const double across = integer(0, 2) == 0 ? 0.0 : real(-0.01, 0.01);
    const bool horizontal = integer(0, 1) == 1;
    const Vec2 b = horizontal ? Vec2{float(a.x + along), float(a.y + across)}
                              : Vec2{float(a.x + across), float(a.y + along)};
    return {{a, b, point(0.1)}};
  }

  // The benchmark's shapes, at a random area that fits the target.
  Triangle exact_area() {
    const double side = std::min(width_, height_);
    const double area =
        std::exp(real(std::log(std::min(0.5, 0.05 * side * side)), std::log(0.2 * side * side)));
    const std::vector<Vec2> v = edgewise::workload::exact_area_triangles(
        1, area, width_, height_, std::uniform_int_distribution<std::uint64_t>()(rng_));
    return {{v[0], v[1], v[2]}};
  }

  // Vertices anywhere in the guard band, and now and then just outside it.
  Triangle huge() {
    const double limit = integer(0, 15) == 0 ? 40000.0 : double(edgewise::kGuardBand) - 1.0;
    auto vertex = [&] { return Vec2{float(real(-limit, limit)), float(real(-limit, limit))}; };
    return {{vertex(), vertex(), vertex()}};
  }

  // Zero area (collinear, repeated vertex), or a NaN or infinite coordinate.
  Triangle degenerate() {
    const Vec2 a = point(0.1), b = point(0.1);
    switch (integer(0, 3)) {
      case 0:
        return {{a, b, Vec2{(a.x + b.x) / 2, (a.y + b.y) / 2}}};
      case 1:
        return {{a, a, b}};
      case 2:
        return {{a, b, Vec2{std::numeric_limits<float>::quiet_NaN(), a.y}}};
      default:
        return {{a, Vec2{b.x, std::numeric_limits<float>::infinity()}, b}};
    }
  }

  int width_, height_;
  std::mt19937_64 rng_;
};

// Shortest text that reads back as the same float.
std::string text(float value) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

struct Arguments {
  int width = 0, height = 0;
  std::uint64_t count = 0;
  std::uint64_t seed = 1;
  std::string output;
};

// An integer in lo..hi, named `what` in messages.
template <class Int>
edgewise::tools::Option add_count(edgewise::tools::CommandLine& command_line,
                                  const std::string& name, const std::string& what, Int& value,
                                  std::uint64_t lo, std::uint64_t hi,
                                  const std::string& description) {
  return edgewise::tools::add_parsed_option(
             command_line, name, value,
             [what, lo, hi](const std::string& text) {
               return static_cast<Int>(edgewise::tools::unsigned_in(what, text, lo, hi));
             },
             description)
      .type_name("");
}

void add_options(edgewise::tools::CommandLine& command_line, Arguments& arguments) {
  command_line.description(kDescription);
  const std::uint64_t max_side = edgewise::kMaxTargetSize;
  add_count(command_line, "W", "width", arguments.width, 1, max_side,
            "the target's width in pixels, 1.." + std::to_string(max_side))
      .required();
  add_count(command_line, "H", "height", arguments.height, 1, max_side,
            "the target's height in pixels, 1.." + std::to_string(max_side))
      .required();
  add_count(command_line, "COUNT", "count", arguments.count, 0, 100'000'000,
            "how many triangles, 0..100000000")
      .required();
  add_count(command_line, "--seed", "seed", arguments.seed, 0,
            std::numeric_limits<std::uint64_t>::max(), "the random generator's seed (default 1)")
      .type_name("N");
  edgewise::tools::add_text_option(command_line, "-o", arguments.output,
                                   "write to FILE (default: standard output)")
      .type_name("FILE");
}

int run(const Arguments& arguments) {
  const int width = arguments.width, height = arguments.height;
  const std::uint64_t count = arguments.count, seed = arguments.seed;
  const std::string& output = arguments.output;
  std::optional<edgewise::tools::OutputStream> file;
  if (!output.empty()) file.emplace(output);
  std::ostream& out = output.empty() ? std::cout : *file;
  out << "# edgewise-random-triangles " << width << ' ' << height << ' ' << count << " --seed "
      << seed << '\n';
  Generators generators(width, height, seed);
  for (std::uint64_t t = 0; t < count; ++t) {
    const Triangle tri = generators.next(t);
    out << text(tri.v[0].x) << ' ' << text(tri.v[0].y) << ' ' << text(tri.v[1].x) << ' '
        << text(tri.v[1].y) << ' ' << text(tri.v[2].x) << ' ' << text(tri.v[2].y) << '\n';
  }
  // Standard output is checked by run_tool.
  if (file) file->finish();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  return edgewise::tools::run_tool(argc, argv, "edgewise-random-triangles",
                                   {"W H COUNT [--seed N] [-o FILE]"},
                                   [&arguments](edgewise::tools::CommandLine& command_line) {
                                     add_options(command_line, arguments);
                                     return [&arguments] { return run(arguments); };
                                   });
}
