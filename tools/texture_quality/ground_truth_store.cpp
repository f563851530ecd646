#include "texture_quality/ground_truth_store.hpp"

#include <iomanip>
#include <optional>
#include <stdexcept>

#include "texture_scene/ground_truth_cache.hpp"

namespace edgewise::texture_quality {
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
  // cached_ground_truth() reads again (the file is still missing), then computes and stores.
  stored.truth = texture_scene::cached_ground_truth(stored.file, texture, WrapMode::repeat,
                                                    WrapMode::repeat, view, region, options);
  stored.computed = true;
  log << "  ground truth computed in ";
  describe(stored.truth.report);
  log << "; stored in " << stored.file.string() << '\n';
  return stored;
}

}  // namespace edgewise::texture_quality
