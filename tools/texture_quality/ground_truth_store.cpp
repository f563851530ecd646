#include "texture_quality/ground_truth_store.hpp"

#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <optional>
#include <stdexcept>

#include "texture_scene/ground_truth_cache.hpp"

namespace edgewise::texture_quality {
namespace {

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace

std::filesystem::path default_cache_directory() {
  for (const char* variable : {"XDG_CACHE_HOME", "HOME"}) {
    const char* value = std::getenv(variable);
    if (value == nullptr || value[0] != '/') continue;  // the XDG spec ignores relative paths
    const std::filesystem::path base(value);
    return variable[0] == 'X' ? base / "edgewise" : base / ".cache" / "edgewise";
  }
  throw std::runtime_error("no cache directory: set XDG_CACHE_HOME or HOME, or give --cache DIR");
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
  stored.file = directory / (name + "_" + hex(fingerprint) + ".ewgt");

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
