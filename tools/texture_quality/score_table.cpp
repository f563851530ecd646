#include "texture_quality/score_table.hpp"

#include <cstdio>
#include <string>

namespace edgewise::texture_quality {
namespace {

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

void print_score_table(std::ostream& out, std::span<const ScoreRow> rows) {
  constexpr const char* kColumns = "  %-22s %-10s %10s %8s %10s %11s";
  char line[160];
  std::snprintf(line, sizeof line, kColumns, "method", "isa", "RMSE", "PSNR dB", "worst",
                "ns/sample");
  out << line << "  front\n";
  for (const ScoreRow& row : rows) {
    std::snprintf(line, sizeof line, kColumns, row.method.c_str(), row.isa.c_str(),
                  formatted("%.4g", row.rmse).c_str(), formatted("%.2f", row.psnr).c_str(),
                  formatted("%.4g", row.worst).c_str(),
                  formatted("%.3g", row.ns_per_sample).c_str());
    out << line << (row.pareto ? "  *\n" : "\n");
  }
}

}  // namespace edgewise::texture_quality
