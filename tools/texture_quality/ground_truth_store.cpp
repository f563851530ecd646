#include "texture_quality/ground_truth_store.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <optional>
#include <stdexcept>
#include <thread>

#include "common/progress.hpp"
#include "texture_scene/ground_truth_cache.hpp"

namespace edgewise::texture_quality {

std::int32_t default_band_rows() {
  return 8 * static_cast<std::int32_t>(std::max(1u, std::thread::hardware_concurrency()));
}

texture_scene::GroundTruth banded_ground_truth(const texture_scene::LinearImage& texture,
                                               const texture_scene::TextureView& view,
                                               const texture_scene::ScreenRegion& region,
                                               const texture_scene::GroundTruthOptions& options,
                                               std::int32_t band_rows) {
  if (band_rows < 1) throw std::invalid_argument("banded_ground_truth: band_rows < 1");
  const auto start = std::chrono::steady_clock::now();
  texture_scene::GroundTruth truth;
  truth.region = region;
  truth.image = texture_scene::LinearImage::filled(region.width, region.height, 0.0f);
  truth.grid.assign(static_cast<std::size_t>(region.width) * region.height, 0);
  texture_scene::GroundTruthReport& report = truth.report;
  tools::Progress progress("  ground truth", region.height, "rows");
  for (std::int32_t first = 0; first < region.height; first += band_rows) {
    progress.update(first);
    const texture_scene::ScreenRegion band_region{region.x0, region.y0 + first, region.width,
                                                  std::min(band_rows, region.height - first)};
    const texture_scene::GroundTruth band = texture_scene::ground_truth(
        texture, WrapMode::repeat, WrapMode::repeat, view, band_region, options);
    std::copy(
        band.image.rgba.begin(), band.image.rgba.end(),
        truth.image.rgba.begin() + static_cast<std::ptrdiff_t>(truth.image.texel_index(0, first)));
    std::copy(band.grid.begin(), band.grid.end(),
              truth.grid.begin() + static_cast<std::ptrdiff_t>(region.width) * first);
    report.pixels += band.report.pixels;
    report.capped_pixels += band.report.capped_pixels;
    report.worst_capped_change =
        std::max(report.worst_capped_change, band.report.worst_capped_change);
    report.worst_converged_change =
        std::max(report.worst_converged_change, band.report.worst_converged_change);
    report.largest_grid = std::max(report.largest_grid, band.report.largest_grid);
    report.samples += band.report.samples;
  }
  progress.finish();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return truth;
}

StoredGroundTruth load_or_compute_ground_truth(const std::filesystem::path& directory,
                                               const std::string& name,
                                               const texture_scene::LinearImage& texture,
                                               const texture_scene::TextureView& view,
                                               std::ostream& log) {
  const texture_scene::ScreenRegion region = view.screen();
  const texture_scene::GroundTruthOptions options;
  const std::uint64_t fingerprint = texture_scene::ground_truth_fingerprint(
      texture, WrapMode::repeat, WrapMode::repeat, view, region, options);
  StoredGroundTruth stored;
  stored.file = texture_scene::ground_truth_file(directory, name, fingerprint);

  const auto describe = [&log](const texture_scene::GroundTruthReport& report) {
    log << std::fixed << std::setprecision(2) << report.seconds << " s, " << std::scientific
        << std::setprecision(2) << double(report.samples) << std::defaultfloat
        << " texture samples, largest grid " << report.largest_grid << ", " << report.capped_pixels
        << " pixels capped";
  };
  if (std::optional<texture_scene::GroundTruth> truth =
          texture_scene::read_ground_truth(stored.file, fingerprint)) {
    stored.truth = std::move(*truth);
    log << "  ground truth read from " << stored.file.string() << " (computed earlier in ";
    describe(stored.truth.report);
    log << ")\n";
    return stored;
  }
  log << "  ground truth: computing " << region.width << "x" << region.height
      << " pixels (minutes for a full-HD ground plane)..." << std::endl;
  stored.truth = banded_ground_truth(texture, view, region, options, default_band_rows());
  texture_scene::write_ground_truth(stored.file, stored.truth, fingerprint);
  stored.computed = true;
  log << "  ground truth computed in ";
  describe(stored.truth.report);
  log << "; stored in " << stored.file.string() << '\n';
  return stored;
}

}  // namespace edgewise::texture_quality
