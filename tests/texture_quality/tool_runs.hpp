// The outputs of edgewise-texture-quality's runs made by this directory's CTest fixtures
// (CMakeLists.txt): a first run that computes every ground truth into an empty cache, with the
// active ISA, OpenImageIO's peer and pictures, a second run of the reference that finds them
// in the cache, and a run of two chosen filters with other level-of-detail settings.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "texture_quality/score_row.hpp"

namespace edgewise::texture_quality::test {

// The fixtures' settings, shared with CMakeLists.txt.
inline constexpr std::string_view kSize = "96x54";
inline constexpr int kWidth = 96, kHeight = 54;
inline constexpr int kSceneCount = 4;  // two textures, two views

inline const std::filesystem::path& runs_directory() {
  static const std::filesystem::path directory = EDGEWISE_TEXTURE_QUALITY_RUNS;
  return directory;
}

// The whole file; fails the test (and returns "") when it cannot be read.
std::string file_text(const std::filesystem::path& path);

// The scores of the first run (first.csv), of the second (second.csv) and of the run of chosen
// filters with the max-of-axes formula and a bias of -0.5 (chosen.csv).
std::vector<ScoreRow> first_scores();
std::vector<ScoreRow> second_scores();
std::vector<ScoreRow> chosen_scores();

// The rows of one scene, in file order.
std::vector<ScoreRow> scene_rows(const std::vector<ScoreRow>& rows, std::string_view texture,
                                 std::string_view view);

// The row of `method` on `isa` in the scene; fails the test (and returns a row of NaNs) when
// there is none or more than one.
ScoreRow find_row(const std::vector<ScoreRow>& rows, std::string_view texture,
                  std::string_view view, std::string_view method, std::string_view isa);

// The ISA of the first run's edgewise rows (every row not from the peer).
std::string first_run_isa(const std::vector<ScoreRow>& rows);

// How often `needle` occurs in `text`.
int count_occurrences(std::string_view text, std::string_view needle);

}  // namespace edgewise::texture_quality::test
