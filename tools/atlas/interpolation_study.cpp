#include "atlas/interpolation_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "draw_probes.hpp"
#include "edgewise/edgewise.hpp"

namespace edgewise::atlas {
namespace {

// The target: a power of two, so that a screen position on the 1/256 grid and a clip w that is
// a power of two pass through clip space and the viewport mapping without rounding.
constexpr int kTargetSize = 1024;

// Triangles given on screen (pixels) with a clip w and an attribute (red, green, blue in [0, 1])
// per vertex.
struct ScreenTriangles {
  std::vector<Vec2> screen;
  std::vector<float> w;
  std::vector<Vec4> colors;
  std::size_t count() const { return screen.size() / 3; }
};

// The positions draw() takes for them, with probes::clip_from_xyw().
std::vector<Vec3> positions_of(const ScreenTriangles& triangles) {
  std::vector<Vec3> positions;
  for (std::size_t i = 0; i < triangles.screen.size(); ++i) {
    positions.push_back(probes::xyw_position(triangles.screen[i].x, triangles.screen[i].y,
                                             triangles.w[i], kTargetSize, kTargetSize));
  }
  return positions;
}

// Error of the drawn colours against the exact perspective-correct value of the vertex colours
// at each covered pixel centre (the three channels, in units of the attribute): the exact value
// takes the screen positions as given (on the 1/256 grid; where w is not a power of two the
// float mapping may move a vertex by a rounding, below 2^-13 px here, so the exact value may
// differ by that much times the attribute's gradient, far below the 1/510 of the 8-bit colour).
struct Error {
  double sum_squares = 0.0, worst = 0.0;
  std::uint64_t values = 0;
  double rmse() const { return values == 0 ? 0.0 : std::sqrt(sum_squares / values); }
};

Error measure_error(const ScreenTriangles& triangles, const DrawOptions& options) {
  Error error;
  const std::vector<Vec3> positions = positions_of(triangles);
  Framebuffer target(kTargetSize, kTargetSize);
  std::vector<std::uint8_t> rgba(std::size_t{kTargetSize} * kTargetSize * 4);
  // One triangle at a time: the study's triangles may overlap.
  for (std::size_t t = 0; t < triangles.count(); ++t) {
    target.clear({0.0f, 0.0f, 0.0f, 0.0f}, 1.0f);
    DrawMesh mesh;
    mesh.positions = std::span(positions).subspan(3 * t, 3);
    mesh.colors = std::span(triangles.colors).subspan(3 * t, 3);
    draw(target, mesh, options);
    target.read_rgba8(rgba);
    const Vec2* v = &triangles.screen[3 * t];
    const double area = (double(v[1].x) - v[0].x) * (double(v[2].y) - v[0].y) -
                        (double(v[1].y) - v[0].y) * (double(v[2].x) - v[0].x);
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({v[0].x, v[1].x, v[2].x}))));
    const int x1 =
        std::min(kTargetSize - 1, static_cast<int>(std::ceil(std::max({v[0].x, v[1].x, v[2].x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({v[0].y, v[1].y, v[2].y}))));
    const int y1 =
        std::min(kTargetSize - 1, static_cast<int>(std::ceil(std::max({v[0].y, v[1].y, v[2].y}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const std::uint8_t* pixel = &rgba[(std::size_t(y) * kTargetSize + x) * 4];
        if (pixel[3] == 0) continue;  // not covered (alpha is 1 wherever drawn)
        const double px = x + 0.5, py = y + 0.5;
        double b[3];
        for (int i = 0; i < 3; ++i) {
          const Vec2 &p = v[(i + 1) % 3], &q = v[(i + 2) % 3];
          b[i] = ((double(q.x) - p.x) * (py - p.y) - (double(q.y) - p.y) * (px - p.x)) / area;
        }
        double weights[3], total = 0.0;
        for (int i = 0; i < 3; ++i) {
          weights[i] = b[i] / triangles.w[3 * t + i];
          total += weights[i];
        }
        for (int c = 0; c < 3; ++c) {
          double exact = 0.0;
          for (int i = 0; i < 3; ++i) {
            const Vec4& colour = triangles.colors[3 * t + i];
            exact += weights[i] / total * (c == 0 ? colour.x : c == 1 ? colour.y : colour.z);
          }
          const double e = std::abs(pixel[c] / 255.0 - exact);
          error.sum_squares += e * e;
          error.worst = std::max(error.worst, e);
          ++error.values;
        }
      }
    }
  }
  return error;
}

// A random triangle of about `extent` px across and aspect ratio about `aspect`, at every angle,
// inside the target, on the 1/256 grid; w of its vertices: `w_low`, `w_high` and one between.
void add_triangle(std::mt19937_64& rng, double extent, double aspect, double w_low, double w_high,
                  ScreenTriangles& out) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double angle = 2.0 * std::numbers::pi * unit(rng);
  const double dx = std::cos(angle), dy = std::sin(angle);
  const double cx = extent + (kTargetSize - 2 * extent) * unit(rng);
  const double cy = extent + (kTargetSize - 2 * extent) * unit(rng);
  const double length = extent / 2.0, width = extent / aspect / 2.0;
  const double skew = length * (unit(rng) - 0.5);
  const double corners[3][2] = {{cx - length * dx, cy - length * dy},
                                {cx + length * dx, cy + length * dy},
                                {cx + skew * dx - width * dy, cy + skew * dy + width * dx}};
  const double middle = w_low + (w_high - w_low) * unit(rng);
  const double ws[3] = {w_low, w_high, middle};
  const int first = static_cast<int>(3 * unit(rng)) % 3;  // which vertex is nearest
  for (int i = 0; i < 3; ++i) {
    out.screen.push_back({static_cast<float>(std::round(corners[i][0] * 256.0) / 256.0),
                          static_cast<float>(std::round(corners[i][1] * 256.0) / 256.0)});
    out.w.push_back(static_cast<float>(ws[(i + first) % 3]));
    out.colors.push_back({static_cast<float>(unit(rng)), static_cast<float>(unit(rng)),
                          static_cast<float>(unit(rng)), 1.0f});
  }
}

DrawOptions options_for(InterpolationMethod method, Perspective perspective, Isa isa) {
  DrawOptions options;
  options.transform = probes::clip_from_xyw();
  options.depth_test = DepthTest::always;
  options.depth_write = false;
  options.interpolation = method;
  options.perspective = perspective;
  options.isa = isa;
  options.threads = 1;
  return options;
}

std::string label(InterpolationMethod method, Perspective perspective) {
  std::string name(name_of(method));
  return perspective == Perspective::affine ? name + ", affine" : name;
}

constexpr const char* kInterpolationPareto = "interpolation-pareto";
constexpr const char* kDepthRatio = "interpolation-depth-ratio";
constexpr const char* kSlivers = "interpolation-slivers";

void interpolation_pareto(const StudySettings& settings, StudyOutput& out) {
  out.add_chart({kInterpolationPareto, "Error against time per fragment, every method and ISA",
                 "ns per fragment", "RMSE against the exact value (attribute in [0, 1])", true,
                 true, ChartKind::scatter, ""});
  std::mt19937_64 rng(0x1e7e);
  ScreenTriangles triangles;
  const int count = settings.quick ? 8 : 64;
  for (int t = 0; t < count; ++t)
    add_triangle(rng, 48.0, 2.0, 1.0, 4.0, triangles);
  const std::vector<Vec3> positions = positions_of(triangles);
  DrawMesh mesh;
  mesh.positions = positions;
  mesh.colors = triangles.colors;
  Framebuffer target(kTargetSize, kTargetSize);
  std::vector<std::pair<InterpolationMethod, Perspective>> methods;
  for (InterpolationMethod method : kInterpolationMethods)
    methods.emplace_back(method, Perspective::correct);
  methods.emplace_back(InterpolationMethod::plane_equations, Perspective::affine);
  std::string best_name;
  double best_ns = 0.0, best_rmse = 0.0, exact_floor = 0.0;
  for (const auto& [method, perspective] : methods) {
    const Error error = measure_error(triangles, options_for(method, perspective, active_isa()));
    for (Isa isa : supported_isas()) {
      const DrawOptions options = options_for(method, perspective, isa);
      const DrawReport report = draw(target, mesh, options);
      const double ns =
          median_nanoseconds(
              "interpolation/" + label(method, perspective) + "/" + std::string(name_of(isa)),
              [&] { draw(target, mesh, options); }, settings.timer) /
          static_cast<double>(std::max<std::uint64_t>(report.fragments, 1));
      out.add(kInterpolationPareto, label(method, perspective), ns, error.rmse(),
              std::string(name_of(isa)));
      if (method == InterpolationMethod::plane_equations && perspective == Perspective::correct &&
          (best_name.empty() || ns < best_ns)) {
        best_name = std::string(name_of(isa));
        best_ns = ns;
        best_rmse = error.rmse();
      }
    }
    if (perspective == Perspective::correct && method != InterpolationMethod::nearest_vertex &&
        method != InterpolationMethod::inverse_distance) {
      exact_floor = std::max(exact_floor, error.rmse());
    }
  }
  char reading[400];
  std::snprintf(reading, sizeof reading,
                "Triangles about 48 px across, w from 1 to 4. The four barycentric methods reach "
                "the 8-bit colour's own rounding (RMSE at most %.4f, 1/255 = %.4f); plane "
                "equations on %s is the fastest of them (%.2f ns per fragment, RMSE %.4f). "
                "Nearest vertex and inverse distance are not interpolation of the value, and "
                "affine weights miss by the depth range.",
                exact_floor, 1.0 / 255.0, best_name.c_str(), best_ns, best_rmse);
  out.set_reading(kInterpolationPareto, reading);
}

void depth_ratio(const StudySettings& settings, StudyOutput& out) {
  out.add_chart({kDepthRatio, "Affine against perspective-correct weights, by depth range",
                 "w_max / w_min across the triangle", "error against the exact value", true, true,
                 ChartKind::line, ""});
  const int count = settings.quick ? 4 : 32;
  double affine_safe = 0.0;  // the largest ratio whose affine worst error is within 1/255
  double correct_worst = 0.0;
  for (double ratio : {1.0, 1.01, 1.03, 1.1, 1.25, 2.0, 4.0, 10.0, 100.0, 1e3, 1e4, 1e6}) {
    std::mt19937_64 rng(0xde9 + static_cast<std::uint64_t>(ratio * 100));
    ScreenTriangles triangles;
    for (int t = 0; t < count; ++t)
      add_triangle(rng, 96.0, 2.0, 1.0, ratio, triangles);
    const Error affine = measure_error(triangles, options_for(InterpolationMethod::plane_equations,
                                                              Perspective::affine, active_isa()));
    const Error correct = measure_error(triangles, options_for(InterpolationMethod::plane_equations,
                                                               Perspective::correct, active_isa()));
    out.add(kDepthRatio, "affine, RMSE", ratio, affine.rmse());
    out.add(kDepthRatio, "affine, worst", ratio, affine.worst);
    out.add(kDepthRatio, "perspective-correct, worst", ratio, correct.worst);
    if (affine.worst <= 1.0 / 255.0) affine_safe = std::max(affine_safe, ratio);
    correct_worst = std::max(correct_worst, correct.worst);
  }
  char reading[400];
  std::snprintf(reading, sizeof reading,
                "Triangles about 96 px across. Affine weights stay within 1/255 of the exact "
                "value up to a depth range of %g here (the derived bound allows 1.0158); "
                "perspective-correct weights stay within %.4f up to w_max / w_min = 1e6, w near "
                "0 against the far vertex (the 8-bit rounding alone is %.4f).",
                affine_safe, correct_worst, 0.5 / 255.0);
  out.set_reading(kDepthRatio, reading);
}

void slivers(const StudySettings& settings, StudyOutput& out) {
  out.add_chart({kSlivers, "Worst error of each method as triangles thin", "aspect ratio",
                 "worst error against the exact value", true, true, ChartKind::line, ""});
  const int count = settings.quick ? 4 : 48;
  double worst_barycentric = 0.0;
  for (double aspect : {1.0, 4.0, 16.0, 64.0, 256.0, 1024.0}) {
    std::mt19937_64 rng(0x511e + static_cast<std::uint64_t>(aspect));
    ScreenTriangles triangles;
    for (int t = 0; t < count; ++t)
      add_triangle(rng, 256.0, aspect, 1.0, 2.0, triangles);
    for (InterpolationMethod method : kInterpolationMethods) {
      const Error error =
          measure_error(triangles, options_for(method, Perspective::correct, active_isa()));
      out.add(kSlivers, std::string(name_of(method)), aspect, error.worst);
      if (method != InterpolationMethod::nearest_vertex &&
          method != InterpolationMethod::inverse_distance) {
        worst_barycentric = std::max(worst_barycentric, error.worst);
      }
    }
  }
  char reading[300];
  std::snprintf(reading, sizeof reading,
                "Triangles 256 px long, w from 1 to 2. The barycentric methods stay within %.4f "
                "of the exact value up to 1024:1 (1/255 = %.4f).",
                worst_barycentric, 1.0 / 255.0);
  out.set_reading(kSlivers, reading);
}

}  // namespace

StudyOutput interpolation_study(const StudySettings& settings, const std::string& cpu) {
  StudyOutput out("interpolation", "Interpolation: every method against the exact value", cpu);
  interpolation_pareto(settings, out);
  depth_ratio(settings, out);
  slivers(settings, out);
  return out;
}

}  // namespace edgewise::atlas
