#include "texture_quality/score_csv.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace edgewise::texture_quality {
namespace {

constexpr int kFieldCount = 10;

void append_text_field(std::string& line, const std::string& field) {
  if (field.find_first_of(",\"\r\n") != std::string::npos) {
    throw std::invalid_argument("score_csv_text: field '" + field + "' holds a separator");
  }
  line += field;
}

// 17 significant digits round-trip every double; one spelling for NaN, whatever its sign.
void append_number(std::string& line, double value) {
  if (std::isnan(value)) {
    line += "nan";
    return;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  line += text;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::runtime_error line_error(std::size_t line_number, const std::string& reason) {
  return std::runtime_error("line " + std::to_string(line_number) + ": " + reason);
}

double parse_number(std::string_view field, std::size_t line_number) {
  double value = 0.0;
  const char* last = field.data() + field.size();
  const auto [end, ec] = std::from_chars(field.data(), last, value);
  if (ec != std::errc() || end != last || field.empty()) {
    throw line_error(line_number, "'" + std::string(field) + "' is not a number");
  }
  return value;
}

std::runtime_error file_error(const std::filesystem::path& path, const std::string& reason) {
  return std::runtime_error(path.string() + ": " + reason);
}

}  // namespace

std::string score_csv_text(std::span<const ScoreRow> rows) {
  std::string text(kScoreCsvHeader);
  text += '\n';
  for (const ScoreRow& row : rows) {
    std::string line;
    for (const std::string* field : {&row.texture, &row.view, &row.size, &row.method, &row.isa}) {
      append_text_field(line, *field);
      line += ',';
    }
    for (double value : {row.rmse, row.psnr, row.worst, row.ns_per_sample}) {
      append_number(line, value);
      line += ',';
    }
    line += row.pareto ? '1' : '0';
    text += line;
    text += '\n';
  }
  return text;
}

std::vector<ScoreRow> parse_score_csv(std::string_view text) {
  std::vector<ScoreRow> rows;
  std::size_t line_number = 0;
  bool header_seen = false;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!header_seen) {
      if (line != kScoreCsvHeader) {
        throw line_error(line_number, "expected the header '" + std::string(kScoreCsvHeader) + "'");
      }
      header_seen = true;
      continue;
    }
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.size() != kFieldCount) {
      throw line_error(line_number, std::to_string(fields.size()) + " fields, expected " +
                                        std::to_string(kFieldCount));
    }
    ScoreRow row;
    row.texture = fields[0];
    row.view = fields[1];
    row.size = fields[2];
    row.method = fields[3];
    row.isa = fields[4];
    row.rmse = parse_number(fields[5], line_number);
    row.psnr = parse_number(fields[6], line_number);
    row.worst = parse_number(fields[7], line_number);
    row.ns_per_sample = parse_number(fields[8], line_number);
    if (fields[9] != "0" && fields[9] != "1") {
      throw line_error(line_number, "pareto '" + std::string(fields[9]) + "' is not 0 or 1");
    }
    row.pareto = fields[9] == "1";
    rows.push_back(row);
  }
  if (!header_seen) throw line_error(1, "empty file, expected a header");
  return rows;
}

std::vector<ScoreRow> read_score_csv(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw file_error(path, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream text;
  text << file.rdbuf();
  try {
    return parse_score_csv(text.str());
  } catch (const std::runtime_error& error) {
    throw file_error(path, error.what());
  }
}

ScoreCsvFile::ScoreCsvFile(const std::filesystem::path& path) : file_(path.string()) {}

void ScoreCsvFile::write(std::span<const ScoreRow> rows) {
  file_.write(score_csv_text(rows));
  file_.finish();
}

}  // namespace edgewise::texture_quality
