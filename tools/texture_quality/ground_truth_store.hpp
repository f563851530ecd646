// Where the tool keeps its ground truths: one file per texture, view and screen size in a cache
// directory (texture_scene/ground_truth_cache.hpp's format), named by the fingerprint of
// everything the result depends on, so that a changed texture, view or evaluator never reads a
// stale file.
#pragma once

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

}  // namespace edgewise::texture_quality
