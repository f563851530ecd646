// The scores of one scene as a table for people: one line per method and ISA, the Pareto front
// (the lowest error for its time) marked with '*'.
#pragma once

#include <ostream>
#include <span>

#include "texture_quality/score_row.hpp"

namespace edgewise::texture_quality {

// Columns: method, ISA, RMSE, PSNR (dB), worst error, ns per sample, front. RMSE and worst are
// printed with 4 significant digits, PSNR with 2 decimals, ns per sample with 3 significant
// digits.
void print_score_table(std::ostream& out, std::span<const ScoreRow> rows);

}  // namespace edgewise::texture_quality
