#include "tool_runs.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "texture_quality/score_csv.hpp"

namespace edgewise::texture_quality::test {
namespace {

std::vector<ScoreRow> scores(const char* name) {
  try {
    return read_score_csv(runs_directory() / name);
  } catch (const std::runtime_error& error) {
    ADD_FAILURE() << error.what();
    return {};
  }
}

}  // namespace

std::string file_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    ADD_FAILURE() << "cannot read " << path;
    return "";
  }
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<ScoreRow> first_scores() {
  return scores("first.csv");
}

std::vector<ScoreRow> second_scores() {
  return scores("second.csv");
}

std::vector<ScoreRow> chosen_scores() {
  return scores("chosen.csv");
}

std::vector<ScoreRow> scene_rows(const std::vector<ScoreRow>& rows, std::string_view texture,
                                 std::string_view view) {
  std::vector<ScoreRow> selected;
  for (const ScoreRow& row : rows) {
    if (row.texture == texture && row.view == view) selected.push_back(row);
  }
  return selected;
}

ScoreRow find_row(const std::vector<ScoreRow>& rows, std::string_view texture,
                  std::string_view view, std::string_view method, std::string_view isa) {
  ScoreRow found;
  int matches = 0;
  for (const ScoreRow& row : rows) {
    if (row.texture == texture && row.view == view && row.method == method && row.isa == isa) {
      found = row;
      ++matches;
    }
  }
  if (matches != 1) {
    ADD_FAILURE() << matches << " rows for " << texture << "/" << view << "/" << method << "/"
                  << isa;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    found.rmse = found.psnr = found.worst = found.ns_per_sample = nan;
  }
  return found;
}

std::string first_run_isa(const std::vector<ScoreRow>& rows) {
  for (const ScoreRow& row : rows) {
    if (row.isa != "oiio") return row.isa;
  }
  ADD_FAILURE() << "no edgewise rows";
  return "";
}

int count_occurrences(std::string_view text, std::string_view needle) {
  int count = 0;
  for (std::size_t at = text.find(needle); at != std::string_view::npos;
       at = text.find(needle, at + needle.size())) {
    ++count;
  }
  return count;
}

}  // namespace edgewise::texture_quality::test
