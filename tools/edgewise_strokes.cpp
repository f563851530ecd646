// edgewise-strokes: a sheet of anti-aliased strokes (path.hpp). Polylines with every join and
// cap, quadratic Bezier curves from hairlines to wide strokes, a spiral of curves and a fan of
// thin lines, stroked, painted into a multisampled target and resolved; prints how many
// segments the flattening took against its formula and the largest distance measured between
// the polylines and the true curves, and the time of each step.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/choice_options.hpp"
#include "common/image_file.hpp"
#include "common/isa_options.hpp"
#include "common/option_values.hpp"
#include "common/run_tool.hpp"
#include "common/usage_error.hpp"
#include "common/value_options.hpp"
#include "edgewise/edgewise.hpp"

namespace {

using namespace edgewise;
using Clock = std::chrono::steady_clock;

constexpr std::int32_t kWidth = 960, kHeight = 540;

// The --tolerance range. Below 2^-10 px, a quarter of the 1/256 px step that vertices snap to, a
// finer flattening cannot show. From 64 px up every curve of the sheet (|P0 - 2 P1 + P2| <= 200
// px) is one chord and every arc (radius <= 12 px) takes its fewest sides, so a larger value
// changes nothing. The whole range is above least_path_tolerance() of the sheet's coordinates
// (below 1000 px: 1.8e-4 px), and keeps the check below to at most about 230 segments per curve.
constexpr float kMinTolerance = 0x1p-10f, kMaxTolerance = 64.0f;

struct Arguments {
  int samples = 8;
  float tolerance = kDefaultPathTolerance;
  ResolveFilter filter = ResolveFilter::box;
  bool srgb = false;
  std::optional<Isa> isa;
  bool exact = false;  // --exact: coverage-weighted blending by exact area instead of samples
  std::optional<std::string> output;
};

struct Stroked {
  Path path;
  StrokeStyle style;
  Vec4 color;
};

// A quadratic Bezier as the sheet stores it, for the flattening's check.
struct Curve {
  Vec2 p0, p1, p2;
};

struct Sheet {
  std::vector<Stroked> strokes;
  std::vector<Curve> curves;
};

Vec4 hue(double h) {
  const auto channel = [h](double offset) {
    return static_cast<float>(0.5 + 0.45 * std::cos(2.0 * std::numbers::pi * (h + offset)));
  };
  return {channel(0.0), channel(2.0 / 3.0), channel(1.0 / 3.0), 1.0f};
}

Sheet make_sheet() {
  Sheet sheet;
  const auto quad = [&sheet](Path& path, Vec2 from, Vec2 control, Vec2 to) {
    path.quad_to(control, to);
    sheet.curves.push_back({from, control, to});
  };
  // Zigzags: one per join (rows), caps butt, round, square (columns).
  int index = 0;
  for (std::size_t row = 0; row < values_of<LineJoin>().size(); ++row) {
    for (std::size_t column = 0; column < values_of<LineCap>().size(); ++column) {
      const LineJoin join = values_of<LineJoin>()[row];
      const LineCap cap = values_of<LineCap>()[column];
      const float x0 = 40.0f + 150.0f * static_cast<float>(column);
      const float y0 = 25.0f + 85.0f * static_cast<float>(row);
      Stroked s;
      s.path.move_to({x0, y0 + 50});
      s.path.line_to({x0 + 30, y0});
      s.path.line_to({x0 + 55, y0 + 55});
      s.path.line_to({x0 + 100, y0 + 10});
      s.style.width = 14.0f;
      s.style.join = join;
      s.style.cap = cap;
      s.color = hue(index++ / 9.0);
      sheet.strokes.push_back(std::move(s));
    }
  }
  // Curves from a hairline to 24 px, round caps.
  const float widths[] = {0.5f, 1.0f, 2.0f, 4.0f, 8.0f, 16.0f, 24.0f};
  for (int i = 0; i < 7; ++i) {
    Stroked s;
    const float y = 345.0f + 27.0f * static_cast<float>(i);
    s.path.move_to({40, y});
    quad(s.path, {40, y}, {230, y - 100}, {420, y});
    s.style.width = widths[i];
    s.style.cap = LineCap::round;
    s.color = {0.95f, 0.95f, 0.9f, 1.0f};
    sheet.strokes.push_back(std::move(s));
  }
  // A spiral of quadratics, 1.5 px, round joins.
  {
    Stroked s;
    const double cx = 700, cy = 150;
    Vec2 from{static_cast<float>(cx + 4), static_cast<float>(cy)};
    s.path.move_to(from);
    for (int k = 0; k < 24; ++k) {
      const double a0 = k * std::numbers::pi / 4, a1 = (k + 1) * std::numbers::pi / 4;
      const double r0 = 4 + 4.5 * k, r1 = 4 + 4.5 * (k + 1);
      const double am = 0.5 * (a0 + a1), rm = 0.5 * (r0 + r1) / std::cos(std::numbers::pi / 8);
      const Vec2 control{static_cast<float>(cx + rm * std::cos(am)),
                         static_cast<float>(cy + rm * std::sin(am))};
      const Vec2 to{static_cast<float>(cx + r1 * std::cos(a1)),
                    static_cast<float>(cy + r1 * std::sin(a1))};
      quad(s.path, from, control, to);
      from = to;
    }
    s.style.width = 1.5f;
    s.style.join = LineJoin::round;
    s.color = {0.4f, 0.85f, 1.0f, 1.0f};
    sheet.strokes.push_back(std::move(s));
  }
  // A fan of thin lines, 1 px: where aliasing shows first.
  for (int k = 0; k < 48; ++k) {
    Stroked s;
    const double a = k * std::numbers::pi / 48;
    s.path.move_to({700, 420});
    s.path.line_to({static_cast<float>(700 + 220 * std::cos(a)),
                    static_cast<float>(420 - 220 * std::sin(a) * 0.45)});
    s.style.width = 1.0f;
    s.color = {1.0f, 0.8f, 0.3f, 1.0f};
    sheet.strokes.push_back(std::move(s));
  }
  return sheet;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The largest distance from the true curve (sampled densely) to its flattened polyline.
double flattening_error(const Curve& c, float tolerance, std::size_t& segments) {
  Path path;
  path.move_to(c.p0);
  path.quad_to(c.p1, c.p2);
  const std::vector<Polyline> lines = flatten(path, tolerance);
  const std::vector<Vec2>& points = lines.front().points;
  segments += points.size() - 1;
  double worst = 0.0;
  for (int j = 0; j <= 2000; ++j) {
    const double t = j / 2000.0, u = 1.0 - t;
    const double x = u * u * c.p0.x + 2 * t * u * c.p1.x + t * t * c.p2.x;
    const double y = u * u * c.p0.y + 2 * t * u * c.p1.y + t * t * c.p2.y;
    double nearest = INFINITY;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      const double ax = points[i].x, ay = points[i].y;
      const double dx = points[i + 1].x - ax, dy = points[i + 1].y - ay;
      const double length_sq = dx * dx + dy * dy;
      const double s =
          length_sq > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / length_sq, 0.0, 1.0) : 0.0;
      nearest = std::min(nearest, std::hypot(x - (ax + s * dx), y - (ay + s * dy)));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

int run(const Arguments& arguments) {
  if (!is_standard_sample_count(arguments.samples)) {
    throw tools::UsageError("--samples " + std::to_string(arguments.samples) +
                            " has no standard pattern (1, 2, 4, 8 or 16)");
  }
  if (!(arguments.tolerance >= kMinTolerance && arguments.tolerance <= kMaxTolerance)) {
    std::ostringstream message;
    message << "--tolerance " << arguments.tolerance << " is outside " << std::setprecision(10)
            << kMinTolerance << " to " << kMaxTolerance << " px";
    throw tools::UsageError(message.str());
  }
  const Isa isa = tools::tool_isa(arguments.isa);
  const Sheet sheet = make_sheet();

  std::size_t segments = 0, formula = 0;
  double worst = 0.0;
  for (const Curve& c : sheet.curves) {
    formula += quad_segments(c.p0, c.p1, c.p2, arguments.tolerance);
    worst = std::max(worst, flattening_error(c, arguments.tolerance, segments));
  }

  auto start = Clock::now();
  std::vector<std::vector<Vec2>> triangles;
  std::size_t triangle_count = 0;
  for (const Stroked& s : sheet.strokes) {
    triangles.push_back(stroke(s.path, s.style, arguments.tolerance));
    triangle_count += triangles.back().size() / 3;
  }
  const double stroke_seconds = seconds_since(start);

  Framebuffer target(kWidth, kHeight, arguments.exact ? 1 : arguments.samples);
  target.clear({0.06f, 0.07f, 0.09f, 1.0f}, 1.0f);
  start = Clock::now();
  std::uint64_t samples = 0;
  for (std::size_t i = 0; i < sheet.strokes.size(); ++i) {
    if (arguments.exact) {
      blend_triangle_areas(target, triangles[i], sheet.strokes[i].color, isa);
    } else {
      samples += paint_triangles(target, triangles[i], sheet.strokes[i].color, isa).fragments;
    }
  }
  const double paint_seconds = seconds_since(start);

  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(kWidth) * kHeight * 4);
  ResolveOptions resolve_options;
  resolve_options.filter = arguments.filter;
  resolve_options.srgb = arguments.srgb;
  start = Clock::now();
  resolve(target, rgba, resolve_options);
  const double resolve_seconds = seconds_since(start);

  std::cout << "edgewise-strokes: " << sheet.strokes.size() << " strokes, " << kWidth << "x"
            << kHeight << ", "
            << (arguments.exact ? "exact-area blending (conflation shows at the triangles' seams)"
                                : std::to_string(arguments.samples) + " samples per pixel, " +
                                      std::string(name_of(arguments.filter)) + " resolve")
            << ", ISA " << name_of(isa) << '\n'
            << "  flattening   " << sheet.curves.size() << " quadratic curves at tolerance "
            << arguments.tolerance << " px: " << segments << " segments (the formula: " << formula
            << "), largest distance from the curves " << std::setprecision(3) << worst << " px\n"
            << "  triangles    " << triangle_count << ", " << samples << " samples painted\n"
            << std::fixed << std::setprecision(2) << "  stroke       " << stroke_seconds * 1e3
            << " ms\n"
            << "  paint        " << paint_seconds * 1e3 << " ms\n"
            << "  resolve      " << resolve_seconds * 1e3 << " ms\n";
  if (worst > arguments.tolerance * 1.0001) {
    std::cerr << "edgewise-strokes: a flattened curve strays beyond the tolerance\n";
    return 1;
  }
  if (arguments.output) {
    tools::ImagePixels image;
    image.width = kWidth;
    image.height = kHeight;
    image.channels = 4;
    image.bytes = rgba;
    image.srgb = arguments.srgb;
    tools::write_image_file(*arguments.output, image);
    std::cout << "  image        " << *arguments.output << '\n';
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  return tools::run_tool(
      argc, argv, "edgewise-strokes",
      {"[--samples N | --exact] [--tolerance PX] [--resolve box|tent|mitchell] [--srgb] [-o FILE]"},
      [&arguments](tools::CommandLine& command_line) {
        command_line.description(
            "Strokes a sheet of polylines and quadratic curves (every join and cap, widths from\n"
            "a hairline to 24 px), paints it into a multisampled target and resolves it.");
        const tools::Option samples =
            tools::add_parsed_option(
                command_line, "--samples", arguments.samples,
                [](const std::string& text) {
                  return static_cast<int>(tools::integer_in("--samples", text, 1, 16));
                },
                "samples per pixel (default 8)")
                .type_name("N");
        tools::add_number_option(command_line, "--tolerance", arguments.tolerance,
                                 "flattening and arc tolerance in px, 0.0009765625 (2^-10) to 64\n"
                                 "(default 0.125)")
            .type_name("PX");
        tools::add_enum_option(command_line, "--resolve", arguments.filter, "the resolve filter");
        command_line.add_flag("--srgb", arguments.srgb, "write sRGB-encoded values (else linear)");
        command_line
            .add_flag("--exact", arguments.exact,
                      "blend each triangle by its exact area instead (one sample per\n"
                      "pixel): shows the conflation at the seams between a stroke's triangles")
            .excludes(samples);
        tools::add_isa_options(command_line, arguments.isa,
                               "the ISA (default: the best of this CPU)",
                               "paint with the reference");
        tools::add_text_option(command_line, "-o", arguments.output, "write the image (PNG or EXR)")
            .type_name("FILE");
        return [&arguments] { return run(arguments); };
      });
}
