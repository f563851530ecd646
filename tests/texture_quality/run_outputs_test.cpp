// What the fixtures' runs printed and wrote: every ground truth computed once and then read from
// the cache, every filter scored with finite figures in every scene, a CSV that reads back
// exactly and agrees with the printed table, the Pareto front as its rule says, and pictures.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "texture_quality/filter_methods.hpp"
#include "texture_quality/oiio_peer.hpp"
#include "texture_quality/pareto_front.hpp"
#include "texture_quality/score_csv.hpp"
#include "texture_quality/score_table.hpp"
#include "tool_runs.hpp"

namespace edgewise::texture_quality::test {
namespace {

constexpr const char* kTextures[] = {"checkerboard", "sinusoids"};
constexpr const char* kViews[] = {"ground_plane", "magnification"};

TEST(FirstRun, ComputedEveryGroundTruth) {
  const std::string out = file_text(runs_directory() / "first.out");
  EXPECT_EQ(count_occurrences(out, "ground truth: computing"), kSceneCount) << out;
  EXPECT_EQ(count_occurrences(out, "ground truth computed in"), kSceneCount) << out;
  EXPECT_EQ(count_occurrences(out, "ground truth read from"), 0) << out;
}

// Only the filters asked for, in filter order, named with their settings, and scored with them:
// the bias moves trilinear's level by more than half a level here, so its error changes.
TEST(ChosenRun, ScoresTheChosenFiltersWithTheirSettings) {
  const std::vector<ScoreRow> rows = chosen_scores();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].method, "trilinear_max_axis_bias-0.5_fixed16");
  EXPECT_EQ(rows[1].method, "ewa_16x_bias-0.5");
  for (const ScoreRow& row : rows) {
    EXPECT_EQ(row.texture, "checkerboard");
    EXPECT_EQ(row.view, "ground_plane");
    EXPECT_TRUE(std::isfinite(row.rmse)) << row.method;
  }
  const std::vector<ScoreRow> first = first_scores();
  const ScoreRow plain =
      find_row(first, "checkerboard", "ground_plane", "trilinear", first_run_isa(first));
  EXPECT_NE(rows[0].rmse, plain.rmse);
  const std::string out = file_text(runs_directory() / "chosen.out");
  EXPECT_EQ(count_occurrences(out, "level of detail max_axis with bias -0.5"), 1) << out;
}

TEST(SecondRun, ReadEveryGroundTruthFromTheCache) {
  const std::string out = file_text(runs_directory() / "second.out");
  EXPECT_EQ(count_occurrences(out, "ground truth read from"), kSceneCount) << out;
  EXPECT_EQ(count_occurrences(out, "computing"), 0) << out;
}

TEST(Scores, EveryFilterInEverySceneWithFiniteFigures) {
  const std::vector<ScoreRow> rows = first_scores();
  const std::string isa = first_run_isa(rows);
  const std::vector<FilterMethod> methods = filter_methods(MethodSettings{});
  EXPECT_EQ(rows.size(), kSceneCount * (methods.size() + std::size(kPeerModeNames)));
  for (const char* texture : kTextures) {
    for (const char* view : kViews) {
      std::vector<ScoreRow> expected;
      for (const FilterMethod& method : methods) {
        expected.push_back(find_row(rows, texture, view, method.name, isa));
      }
      for (std::string_view mode : kPeerModeNames) {
        expected.push_back(find_row(rows, texture, view, "oiio_" + std::string(mode), "oiio"));
      }
      for (const ScoreRow& row : expected) {
        SCOPED_TRACE(std::string(texture) + "/" + view + "/" + row.method + "/" + row.isa);
        EXPECT_EQ(row.size, kSize);
        EXPECT_TRUE(std::isfinite(row.rmse) && row.rmse >= 0.0) << row.rmse;
        EXPECT_TRUE(std::isfinite(row.psnr)) << row.psnr;
        // The largest difference is at least the root mean square of them all.
        EXPECT_TRUE(std::isfinite(row.worst) && row.worst >= row.rmse) << row.worst;
        EXPECT_TRUE(std::isfinite(row.ns_per_sample) && row.ns_per_sample > 0.0)
            << row.ns_per_sample;
        // 10 log10(1 / rmse^2), peak 1 (image_metrics.hpp); both printed from one double.
        EXPECT_NEAR(row.psnr, -20.0 * std::log10(row.rmse), 1e-9 * std::abs(row.psnr));
      }
    }
  }
}

TEST(Scores, CsvReadsBackToTheSameText) {
  const std::string text = file_text(runs_directory() / "first.csv");
  EXPECT_EQ(score_csv_text(parse_score_csv(text)), text);
}

TEST(Scores, PrintedTableHoldsTheCsvFigures) {
  // The table printed from the CSV's rows, scene by scene, must appear in the run's output as
  // it is: the table and the CSV come from the same figures.
  const std::vector<ScoreRow> rows = first_scores();
  const std::string out = file_text(runs_directory() / "first.out");
  for (const char* texture : kTextures) {
    for (const char* view : kViews) {
      std::ostringstream table;
      print_score_table(table, scene_rows(rows, texture, view));
      EXPECT_NE(out.find(table.str()), std::string::npos) << texture << "/" << view << ":\n"
                                                          << table.str();
    }
  }
}

TEST(Scores, ParetoFlagsFollowTheRule) {
  const std::vector<ScoreRow> rows = first_scores();
  for (const char* texture : kTextures) {
    for (const char* view : kViews) {
      const std::vector<ScoreRow> scene = scene_rows(rows, texture, view);
      std::vector<CostAndError> points;
      std::vector<bool> flags;
      for (const ScoreRow& row : scene) {
        points.push_back({row.ns_per_sample, row.rmse});
        flags.push_back(row.pareto);
      }
      EXPECT_EQ(flags, pareto_front(points)) << texture << "/" << view;
      // The fastest method and the most accurate one are always on it.
      EXPECT_NE(std::count(flags.begin(), flags.end(), true), 0) << texture << "/" << view;
    }
  }
}

TEST(Images, GroundTruthAndEveryResultAndError) {
  const std::vector<ScoreRow> rows = first_scores();
  std::set<std::string> names;
  for (const char* texture : kTextures) {
    for (const char* view : kViews) {
      names.insert(std::string(texture) + "_" + view + "_" + std::string(kSize) + "_ground_truth");
    }
  }
  for (const ScoreRow& row : rows) {
    const std::string name =
        row.texture + "_" + row.view + "_" + row.size + "_" + row.method + "_" + row.isa;
    names.insert(name);
    names.insert(name + "_error");
  }
  EXPECT_EQ(names.size(), kSceneCount + 2 * rows.size());
  for (const std::string& name : names) {
    const std::string path = (runs_directory() / "images" / (name + ".png")).string();
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input) << path << ": " << OIIO::geterror();
    EXPECT_EQ(input->spec().width, kWidth) << path;
    EXPECT_EQ(input->spec().height, kHeight) << path;
    EXPECT_EQ(input->spec().nchannels, 3) << path;
  }
}

}  // namespace
}  // namespace edgewise::texture_quality::test
