// Ground truth on disk: computing a full-screen ground truth takes minutes, so tools and
// benchmarks keep it in a raw file keyed by a fingerprint of everything it depends on.
//
// File layout (little-endian): the 8 bytes "EWGTRUTH", uint32 format version, uint64
// fingerprint, int32 x0, y0, width, height, then the report (int64 pixels, int64 capped_pixels,
// float64 worst_capped_change, float64 worst_converged_change, int32 largest_grid, int64
// samples, float64 seconds), then width x height x 4 float32 (linear RGBA, row-major), then
// width x height int32 (each pixel's final grid n).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "texture_scene/ground_truth.hpp"

namespace edgewise::texture_scene {

// A 64-bit FNV-1a hash of the texture (size and values), the wrap modes, the view (size and
// mapping coefficients), the region, the options that change the result (tolerance, grids; not
// threads) and the evaluator's version.
std::uint64_t ground_truth_fingerprint(const LinearImage& texture, WrapMode wrap_s, WrapMode wrap_t,
                                       const TextureView& view, const ScreenRegion& region,
                                       const GroundTruthOptions& options);

// Writes through a temporary file renamed into place, so a reader never sees half a file.
// Throws std::runtime_error when the file cannot be written.
void write_ground_truth(const std::filesystem::path& path, const GroundTruth& truth,
                        std::uint64_t fingerprint);

// The stored ground truth, or nullopt when the file is missing, is not a ground-truth file of
// this format version, has another fingerprint, or is truncated or inconsistent: in every case
// the caller should compute it again.
std::optional<GroundTruth> read_ground_truth(const std::filesystem::path& path,
                                             std::uint64_t fingerprint);

// Where ground truths are kept: $XDG_CACHE_HOME/edgewise when XDG_CACHE_HOME is set and
// absolute, else $HOME/.cache/edgewise. Throws std::runtime_error when neither is usable.
std::filesystem::path default_cache_directory();

// The file of a ground truth in `directory`: "<name>_<fingerprint as 16 hex digits>.ewgt".
std::filesystem::path ground_truth_file(const std::filesystem::path& directory,
                                        const std::string& name, std::uint64_t fingerprint);

// read_ground_truth if it succeeds; otherwise ground_truth() then write_ground_truth.
GroundTruth cached_ground_truth(const std::filesystem::path& path, const LinearImage& texture,
                                WrapMode wrap_s, WrapMode wrap_t, const TextureView& view,
                                const ScreenRegion& region, const GroundTruthOptions& options = {});

}  // namespace edgewise::texture_scene
