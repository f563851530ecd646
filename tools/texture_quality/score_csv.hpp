// The scores as CSV, one row per texture / view / method / ISA, for charts and for comparing
// runs. Columns:
//   texture,view,size,method,isa,rmse,psnr_db,worst,ns_per_sample,pareto
// Numbers are written with 17 significant digits, so reading a file back gives the same doubles
// ("inf", "-inf" and "nan" where a figure is not finite); pareto is 1 or 0.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/output_file.hpp"
#include "texture_quality/score_row.hpp"

namespace edgewise::texture_quality {

inline constexpr std::string_view kScoreCsvHeader =
    "texture,view,size,method,isa,rmse,psnr_db,worst,ns_per_sample,pareto";

// The header line and one line per row. Throws std::invalid_argument for a text field holding
// a comma, a quote or a line break.
std::string score_csv_text(std::span<const ScoreRow> rows);

// The rows of score_csv_text()'s output. Throws std::runtime_error("line N: reason") for a
// missing or different header, a wrong number of fields, or a field that is not a number (or
// 0/1 for pareto).
std::vector<ScoreRow> parse_score_csv(std::string_view text);

// Reads and parses a CSV file. Throws std::runtime_error("PATH: reason").
std::vector<ScoreRow> read_score_csv(const std::filesystem::path& path);

// A CSV file opened (and truncated) at construction, so that an unwritable path is found before
// any work is done, and written once the scores are known (common/output_file.hpp: every write
// and the close checked; a file never finished is removed).
class ScoreCsvFile {
 public:
  // Throws std::runtime_error("PATH: cannot write: reason").
  explicit ScoreCsvFile(const std::filesystem::path& path);
  // Writes the rows and closes the file. Throws std::runtime_error("PATH: cannot write: reason").
  void write(std::span<const ScoreRow> rows);

 private:
  tools::OutputFile file_;
};

}  // namespace edgewise::texture_quality
