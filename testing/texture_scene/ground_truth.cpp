#include "texture_scene/ground_truth.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <thread>

namespace edgewise::texture_scene {
namespace {

constexpr std::int32_t kMaxGrid = 1 << 16;

void check_options(const GroundTruthOptions& options) {
  if (!(options.tolerance > 0.0) || options.initial_grid < 1 ||
      options.max_grid < options.initial_grid || options.max_grid > kMaxGrid ||
      options.max_grid % options.initial_grid != 0 || options.threads < 0)
    throw std::invalid_argument("ground_truth: option out of range");
  const std::int32_t ratio = options.max_grid / options.initial_grid;
  if ((ratio & (ratio - 1)) != 0)
    throw std::invalid_argument("ground_truth: max_grid is not initial_grid times a power of 2");
}

struct PixelResult {
  double value[4];
  std::int32_t grid;
  double last_change;
  std::int64_t samples;
};

PixelResult converge_pixel(const BilinearReconstruction& texture, const TextureView& view,
                           std::int32_t i, std::int32_t j, const GroundTruthOptions& options) {
  PixelResult result{};
  std::int32_t n = options.initial_grid;
  pixel_average(texture, view, i, j, n, result.value);
  result.samples = std::int64_t{n} * n;
  result.last_change = std::numeric_limits<double>::infinity();
  while (n < options.max_grid) {
    n *= 2;
    double finer[4];
    pixel_average(texture, view, i, j, n, finer);
    result.samples += std::int64_t{n} * n;
    result.last_change = 0.0;
    for (int c = 0; c < 4; ++c) {
      result.last_change = std::max(result.last_change, std::abs(finer[c] - result.value[c]));
      result.value[c] = finer[c];
    }
    if (result.last_change < options.tolerance) break;
  }
  result.grid = n;
  return result;
}

void merge(GroundTruthReport& into, const GroundTruthReport& from) {
  into.pixels += from.pixels;
  into.capped_pixels += from.capped_pixels;
  into.worst_capped_change = std::max(into.worst_capped_change, from.worst_capped_change);
  into.worst_converged_change = std::max(into.worst_converged_change, from.worst_converged_change);
  into.largest_grid = std::max(into.largest_grid, from.largest_grid);
  into.samples += from.samples;
}

}  // namespace

void pixel_average(const BilinearReconstruction& texture, const TextureView& view, std::int32_t i,
                   std::int32_t j, std::int32_t n, double out[4]) {
  // Checked per estimate, not per sample.
  view.check_region({i, j, 1, 1});
  if (n < 1 || n > kMaxGrid) throw std::invalid_argument("pixel_average: grid outside [1, 65536]");
  const ProjectiveMap& map = view.map();
  const double step = 1.0 / n;
  double total[4] = {0.0, 0.0, 0.0, 0.0};
  for (std::int32_t b = 0; b < n; ++b) {
    const double y = j + (b + 0.5) * step;
    // The y terms of the three rows, once per grid row.
    const double s_base = map.s_row[1] * y + map.s_row[2];
    const double t_base = map.t_row[1] * y + map.t_row[2];
    const double w_base = map.w_row[1] * y + map.w_row[2];
    // Summed per grid row first: n values per partial sum keeps the rounding at ~n ulps.
    double row[4] = {0.0, 0.0, 0.0, 0.0};
    for (std::int32_t a = 0; a < n; ++a) {
      const double x = i + (a + 0.5) * step;
      const double inverse_w = 1.0 / (map.w_row[0] * x + w_base);
      double value[4];
      texture.evaluate((map.s_row[0] * x + s_base) * inverse_w,
                       (map.t_row[0] * x + t_base) * inverse_w, value);
      for (int c = 0; c < 4; ++c)
        row[c] += value[c];
    }
    for (int c = 0; c < 4; ++c)
      total[c] += row[c];
  }
  const double count = double(n) * n;
  for (int c = 0; c < 4; ++c)
    out[c] = total[c] / count;
}

GroundTruth ground_truth(const LinearImage& texture, WrapMode wrap_s, WrapMode wrap_t,
                         const TextureView& view, const ScreenRegion& region,
                         const GroundTruthOptions& options) {
  view.check_region(region);
  check_options(options);
  const BilinearReconstruction reconstruction(texture, wrap_s, wrap_t);
  const auto start = std::chrono::steady_clock::now();

  GroundTruth truth;
  truth.region = region;
  truth.image = LinearImage::filled(region.width, region.height, 0.0f);
  truth.grid.assign(static_cast<std::size_t>(region.width) * region.height, 0);

  // Rows cost very different amounts (far rows of a ground plane take the most): each worker
  // takes the next row left.
  std::atomic<std::int32_t> next_row{0};
  const int thread_count = std::max(
      1, std::min(options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency()),
                  region.height));
  std::vector<GroundTruthReport> reports(static_cast<std::size_t>(thread_count));
  auto work = [&](GroundTruthReport& report) {
    for (std::int32_t row = next_row++; row < region.height; row = next_row++) {
      for (std::int32_t column = 0; column < region.width; ++column) {
        const PixelResult pixel =
            converge_pixel(reconstruction, view, region.x0 + column, region.y0 + row, options);
        float* out = truth.image.texel(column, row);
        for (int c = 0; c < 4; ++c)
          out[c] = round_to_float(pixel.value[c]);
        truth.grid[static_cast<std::size_t>(row) * region.width + column] = pixel.grid;
        ++report.pixels;
        report.samples += pixel.samples;
        report.largest_grid = std::max(report.largest_grid, pixel.grid);
        if (pixel.last_change < options.tolerance) {
          report.worst_converged_change =
              std::max(report.worst_converged_change, pixel.last_change);
        } else {
          ++report.capped_pixels;
          report.worst_capped_change = std::max(report.worst_capped_change, pixel.last_change);
        }
      }
    }
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < thread_count; ++t)
    workers.emplace_back(work, std::ref(reports[t]));
  work(reports[0]);
  for (std::thread& worker : workers)
    worker.join();

  for (const GroundTruthReport& report : reports)
    merge(truth.report, report);
  truth.report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return truth;
}

}  // namespace edgewise::texture_scene
