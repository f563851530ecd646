// The scores' CSV: what is written reads back as the same doubles, and a malformed file is
// refused with the line that is wrong.
#include "texture_quality/score_csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/temp_directory.hpp"

namespace edgewise::texture_quality {
namespace {

using edgewise::scene::test::TempDirectory;

ScoreRow row(std::string method, double rmse, double ns, bool pareto) {
  ScoreRow r;
  r.texture = "checkerboard";
  r.view = "ground_plane";
  r.size = "480x270";
  r.method = std::move(method);
  r.isa = "avx2";
  r.rmse = rmse;
  r.psnr = -20.0 * std::log10(rmse);
  r.worst = 3.0 * rmse;
  r.ns_per_sample = ns;
  r.pareto = pareto;
  return r;
}

std::string expect_line_error(const std::string& text) {
  try {
    parse_score_csv(text);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

TEST(ScoreCsv, RoundTripsEveryDoubleExactly) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<ScoreRow> rows = {row("trilinear", 0.1, 4.25, true),
                                row("ewa_16x", 1.0 / 3.0, 61.7, false)};
  ScoreRow extremes = row("nearest", 0.0, std::numeric_limits<double>::denorm_min(), true);
  extremes.psnr = inf;  // identical images
  extremes.worst = std::numeric_limits<double>::max();
  rows.push_back(extremes);
  ScoreRow broken = row("bicubic_catmull_rom", inf, 1e-300, false);
  broken.psnr = -inf;
  rows.push_back(broken);

  const std::string text = score_csv_text(rows);
  EXPECT_EQ(text.substr(0, text.find('\n')), kScoreCsvHeader);
  EXPECT_EQ(parse_score_csv(text), rows);
  EXPECT_EQ(score_csv_text(parse_score_csv(text)), text);
}

TEST(ScoreCsv, NanReadsBackAsNan) {
  ScoreRow nan_row = row("ewa_16x", std::numeric_limits<double>::quiet_NaN(), 1.0, false);
  nan_row.worst = -std::numeric_limits<double>::quiet_NaN();
  const std::vector<ScoreRow> back = parse_score_csv(score_csv_text(std::vector{nan_row}));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_TRUE(std::isnan(back[0].rmse));
  EXPECT_TRUE(std::isnan(back[0].worst));
}

TEST(ScoreCsv, HeaderOnlyIsNoRows) {
  EXPECT_TRUE(parse_score_csv(std::string(kScoreCsvHeader) + "\n").empty());
  EXPECT_TRUE(parse_score_csv(std::string(kScoreCsvHeader) + "\r\n").empty());
}

TEST(ScoreCsv, MalformedFilesNameTheLine) {
  const std::string header = std::string(kScoreCsvHeader) + "\n";
  const std::string good = "c,g,96x54,nearest,avx2,0.5,6.02,1,2.5,1\n";
  EXPECT_NE(expect_line_error("").find("line 1"), std::string::npos);
  EXPECT_NE(expect_line_error("texture,view\n" + good).find("line 1: expected the header"),
            std::string::npos);
  EXPECT_NE(expect_line_error(header + good + "c,g,96x54,nearest,avx2,0.5,6.02,1,2.5\n")
                .find("line 3: 9 fields, expected 10"),
            std::string::npos);
  EXPECT_NE(expect_line_error(header + "c,g,96x54,nearest,avx2,0.5x,6.02,1,2.5,1\n")
                .find("line 2: '0.5x' is not a number"),
            std::string::npos);
  EXPECT_NE(expect_line_error(header + "c,g,96x54,nearest,avx2,,6.02,1,2.5,1\n")
                .find("line 2: '' is not a number"),
            std::string::npos);
  EXPECT_NE(expect_line_error(header + "c,g,96x54,nearest,avx2,0.5,6.02,1,2.5,yes\n")
                .find("line 2: pareto 'yes' is not 0 or 1"),
            std::string::npos);
}

TEST(ScoreCsv, SeparatorsInNamesAreRefused) {
  ScoreRow bad = row("a,b", 0.1, 1.0, false);
  EXPECT_THROW(score_csv_text(std::vector{bad}), std::invalid_argument);
  bad.method = "a\nb";
  EXPECT_THROW(score_csv_text(std::vector{bad}), std::invalid_argument);
}

TEST(ScoreCsvFile, WritesWhatReadScoreCsvReads) {
  TempDirectory directory;
  const std::filesystem::path path = directory.path() / "scores.csv";
  const std::vector<ScoreRow> rows = {row("trilinear", 0.1, 4.25, true)};
  ScoreCsvFile file(path);
  file.write(rows);
  EXPECT_EQ(read_score_csv(path), rows);
}

TEST(ScoreCsvFile, UnwritableAndMissingPathsThrowWithThePath) {
  TempDirectory directory;
  // A directory cannot be opened as a file; neither can a path under a missing directory.
  for (const std::filesystem::path& path :
       {directory.path(), directory.path() / "missing" / "scores.csv"}) {
    try {
      ScoreCsvFile file(path);
      ADD_FAILURE() << "opened " << path;
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find(path.string() + ": cannot write"), std::string::npos)
          << error.what();
    }
  }
  try {
    read_score_csv(directory.path() / "missing.csv");
    ADD_FAILURE() << "read a missing file";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("missing.csv: cannot open"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace edgewise::texture_quality
