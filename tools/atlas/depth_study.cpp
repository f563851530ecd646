#include "atlas/depth_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/output_file.hpp"
#include "draw_probes.hpp"
#include "edgewise/edgewise.hpp"

namespace edgewise::atlas {
namespace {

constexpr int kSize = 64;  // the target of the separation tests, square

enum class Encoding { standard, reversed, linear };

const char* name_of(Encoding encoding) {
  switch (encoding) {
    case Encoding::reversed:
      return "reversed z/w (greater, cleared to 0)";
    case Encoding::linear:
      return "linear depth (w-buffer, computed)";
    case Encoding::standard:
      break;
  }
  return "z/w (less, cleared to 1)";
}

// Whether the nearer of two planes, at `near_plane` and `far_plane`, wins at every pixel when
// the farther one is drawn first.
bool resolved(Encoding encoding, float near, float far, double near_plane, double far_plane) {
  if (encoding == Encoding::linear) {
    const auto stored = [&](double d) { return static_cast<float>((d - near) / (far - near)); };
    return stored(near_plane) < stored(far_plane);
  }
  return probes::nearer_plane_wins(encoding == Encoding::reversed, near, far,
                                   static_cast<float>(near_plane), static_cast<float>(far_plane),
                                   kSize);
}

// The smallest relative separation s (the farther plane at distance (1 + s)) that resolves, by
// bisection of log s in [1e-9, the far plane]; NaN where even the largest does not.
double smallest_separation(Encoding encoding, float near, float far, double distance) {
  double lo = std::log(1e-9), hi = std::log(far / distance * 0.999 - 1.0);
  if (!(hi > lo) || !resolved(encoding, near, far, distance, distance * (1.0 + std::exp(hi))))
    return NAN;
  if (resolved(encoding, near, far, distance, distance * (1.0 + std::exp(lo)))) return 1e-9;
  for (int step = 0; step < 40; ++step) {
    const double mid = (lo + hi) / 2.0;
    (resolved(encoding, near, far, distance, distance * (1.0 + std::exp(mid))) ? hi : lo) = mid;
  }
  return std::exp(hi);
}

std::string chart_id(double ratio) {
  return "depth-resolution-" + std::to_string(static_cast<long long>(ratio));
}

void separation_chart(double near, double far, int points, StudyOutput& out) {
  const std::string id = chart_id(far / near);
  char title[128];
  std::snprintf(title, sizeof title,
                "Smallest separation resolved, far / near = %g (near %g, far %g)", far / near, near,
                far);
  out.add_chart({id, title, "distance / near", "smallest separation / distance", true, true,
                 ChartKind::line, ""});
  double at_half[3] = {NAN, NAN, NAN};
  for (int i = 0; i < points; ++i) {
    // Log-spaced from just past the near plane to 0.8 of the far distance.
    const double distance = near * std::pow(far / near * 0.8, (i + 0.5) / points);
    for (Encoding encoding : {Encoding::standard, Encoding::reversed, Encoding::linear}) {
      // Where a distance falls within a rounding step moves its own threshold by up to a step:
      // the worst of eight distances 1% apart is the separation resolved at all of them.
      double s = 0.0;
      for (int k = 0; k < 8; ++k) {
        s = std::max(s, smallest_separation(encoding, static_cast<float>(near),
                                            static_cast<float>(far), distance * (1.0 + 0.01 * k)));
      }
      if (std::isnan(s)) continue;
      out.add(id, name_of(encoding), distance / near, s);
      if (distance <= far / 2.0) at_half[static_cast<int>(encoding)] = s;
    }
  }
  char reading[400];
  std::snprintf(reading, sizeof reading,
                "Lower is better. Towards half the far distance, z/w resolves surfaces %.2g of "
                "the distance apart, reversed depth %.2g and a linear float32 depth %.2g: "
                "reversed depth spends float32's exponent where z/w crowds its values.",
                at_half[0], at_half[1], at_half[2]);
  out.set_reading(id, reading);
}

// Binary PPM: a format plot_atlas.py reads through matplotlib without a library of our own.
void write_ppm(const std::filesystem::path& path, const Framebuffer& target) {
  tools::OutputStream file(path.string());
  file << "P6\n" << target.width() << ' ' << target.height() << "\n255\n";
  for (int y = 0; y < target.height(); ++y) {
    for (int x = 0; x < target.width(); ++x) {
      const std::uint32_t c = target.color(x, y);
      const char rgb[3] = {static_cast<char>(c & 0xFF), static_cast<char>((c >> 8) & 0xFF),
                           static_cast<char>((c >> 16) & 0xFF)};
      file.write(rgb, 3);
    }
  }
  file.finish();
}

// Two triangles that pass through each other, seen in orthographic projection: drawn with
// depth interpolated per pixel, and with each triangle's vertices moved to its mean depth.
void why_interpolate_z(const std::string& dir, StudyOutput& out) {
  constexpr int kImage = 256;
  const std::vector<Vec3> positions{
      {-0.9f, -0.7f, -0.2f}, {0.9f, -0.7f, -0.8f}, {0.0f, 0.9f, -0.5f},    // leaning back
      {-0.8f, 0.6f, -0.9f},  {0.8f, 0.6f, -0.1f},  {0.0f, -0.9f, -0.5f}};  // leaning the other way
  std::vector<Vec3> flat(positions.begin(), positions.end());
  for (int t = 0; t < 2; ++t) {
    const float mean = (flat[3 * t].z + flat[3 * t + 1].z + flat[3 * t + 2].z) / 3.0f;
    for (int i = 0; i < 3; ++i)
      flat[3 * t + i].z = mean;
  }
  const std::vector<Vec4> colours = {{0.9f, 0.3f, 0.2f, 1}, {0.9f, 0.3f, 0.2f, 1},
                                     {0.9f, 0.3f, 0.2f, 1}, {0.2f, 0.5f, 0.9f, 1},
                                     {0.2f, 0.5f, 0.9f, 1}, {0.2f, 0.5f, 0.9f, 1}};
  DrawOptions options;
  options.transform = orthographic(-1.0f, 1.0f, -1.0f, 1.0f, 0.0f, 1.0f);
  options.threads = 1;
  Framebuffer per_pixel(kImage, kImage), per_triangle(kImage, kImage);
  const std::pair<Framebuffer*, const std::vector<Vec3>*> drawings[] = {{&per_pixel, &positions},
                                                                        {&per_triangle, &flat}};
  for (auto [target, mesh_positions] : drawings) {
    target->clear({1.0f, 1.0f, 1.0f, 1.0f}, 1.0f);
    DrawMesh mesh;
    mesh.positions = *mesh_positions;
    mesh.colors = colours;
    draw(*target, mesh, options);
  }
  write_ppm(std::filesystem::path(dir) / "depth-per-pixel.ppm", per_pixel);
  write_ppm(std::filesystem::path(dir) / "depth-per-triangle.ppm", per_triangle);
  std::uint64_t differing = 0;
  for (int y = 0; y < kImage; ++y) {
    for (int x = 0; x < kImage; ++x)
      differing += per_pixel.color(x, y) != per_triangle.color(x, y);
  }
  constexpr const char* kId = "depth-why-interpolate-z";
  out.add_chart({kId, "Why interpolate z: two triangles passing through each other", "", "", false,
                 false, ChartKind::images, ""});
  out.add(kId, "depth interpolated per pixel", "depth-per-pixel.ppm", 0.0);
  out.add(kId, "one depth per triangle (its mean)", "depth-per-triangle.ppm", 0.0);
  char reading[300];
  std::snprintf(reading, sizeof reading,
                "With depth per pixel each triangle is in front where it is nearer, and the "
                "crossing is a straight line; with one depth per triangle the one whose mean is "
                "nearer hides the other wherever they overlap (%llu of %d pixels differ).",
                static_cast<unsigned long long>(differing), kImage * kImage);
  out.set_reading(kId, reading);
}

}  // namespace

StudyOutput depth_study(const StudySettings& settings, const std::string& cpu,
                        const std::string& dir) {
  StudyOutput out("depth", "Depth: z/w against reversed and linear depth", cpu);
  const int points = settings.quick ? 4 : 16;
  separation_chart(0.1, 100.0, points, out);
  separation_chart(0.01, 1000.0, points, out);
  why_interpolate_z(dir, out);
  return out;
}

}  // namespace edgewise::atlas
