// Where the tool keeps its ground truths: one file per texture, view and screen size in a cache
// directory (texture_scene/ground_truth_cache.hpp's format), named by the fingerprint of
// everything the result depends on, so that a changed texture, view or evaluator never reads a
// stale file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>

#include "texture_scene/ground_truth.hpp"
#include "texture_scene/ground_truth_cache.hpp"
#include "texture_scene/linear_image.hpp"
#include "texture_scene/texture_view.hpp"

namespace edgewise::texture_quality {

using texture_scene::default_cache_directory;

struct StoredGroundTruth {
  texture_scene::GroundTruth truth;
  std::filesystem::path file;
  bool computed = false;  // false: read from `file`
};

// The whole screen's ground truth for `texture` seen through `view` with repeat wrap, read from
// `directory` when a file with its fingerprint is there, otherwise computed (with the default
// GroundTruthOptions) and stored. `name` (letters, digits, '_') starts the file's name. Says on
// `log` which it does, and how long the computation took; while it computes, a terminal on
// standard error shows the rows done (common/progress.hpp). Throws std::runtime_error when the
// file cannot be written.
StoredGroundTruth load_or_compute_ground_truth(const std::filesystem::path& directory,
                                               const std::string& name,
                                               const texture_scene::LinearImage& texture,
                                               const texture_scene::TextureView& view,
                                               std::ostream& log);

// texture_scene::ground_truth() of `region` with repeat wrap, computed `band_rows` rows at a time
// to show its progress: every pixel is computed on its own, so the image and the grid are the
// one call's, the report merged from the bands' (seconds: the whole computation's). Throws
// std::invalid_argument when band_rows < 1.
texture_scene::GroundTruth banded_ground_truth(const texture_scene::LinearImage& texture,
                                               const texture_scene::TextureView& view,
                                               const texture_scene::ScreenRegion& region,
                                               const texture_scene::GroundTruthOptions& options,
                                               std::int32_t band_rows);
// 8 rows per hardware thread: ground_truth()'s threads take a band's rows one at a time, so at
// a band's end one waits for the other's last row, about 6% of the band's time, and the progress
// moves every few seconds even on the far rows of a full-HD ground plane.
std::int32_t default_band_rows();

}  // namespace edgewise::texture_quality
