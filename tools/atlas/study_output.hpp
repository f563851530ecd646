// What a study of the method atlas writes (tools/edgewise-atlas): its numbers as a CSV, one row
// per point (chart, series, x, y, label), and its charts' descriptions as JSON (titles, axes,
// scales, a line of reading each, the CPU), from which tools/atlas/plot_atlas.py draws the charts
// and the page.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace edgewise::atlas {

// images: each point's x names an image file of the output folder, its series the caption.
enum class ChartKind { line, bar, scatter, images };

struct Chart {
  std::string id;  // file name stem of the chart: letters, digits and '-'
  std::string title;
  std::string x_label, y_label;
  bool x_log = false, y_log = false;
  ChartKind kind = ChartKind::line;
  std::string reading;  // one or two sentences: what the chart says
};

struct Point {
  std::string chart, series;
  std::string x;  // a number, or a category for bar charts
  double y = 0.0;
  std::string label;  // what tells the series' points apart (its ISA), or empty
};

class StudyOutput {
 public:
  StudyOutput(std::string study, std::string title, std::string cpu);
  void add_chart(Chart chart);
  // Sets the reading line of a chart added before (found by id); throws std::logic_error if none.
  void set_reading(const std::string& chart, std::string reading);
  void add(const std::string& chart, const std::string& series, double x, double y);
  // A point of a scatter chart whose series has several: `label` says which one it is.
  void add(const std::string& chart, const std::string& series, double x, double y,
           const std::string& label);
  void add(const std::string& chart, const std::string& series, const std::string& category,
           double y);
  // Writes <dir>/<study>.csv and <dir>/<study>.json; throws std::runtime_error naming the file
  // that could not be written.
  void write(const std::filesystem::path& dir) const;

 private:
  std::string study_, title_, cpu_;
  std::vector<Chart> charts_;
  std::vector<Point> points_;
};

// x formatted with enough digits to read back the same double.
std::string exact_decimal(double x);

}  // namespace edgewise::atlas
