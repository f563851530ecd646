#include "atlas/study_output.hpp"

#include <charconv>
#include <stdexcept>
#include <utility>

#include "common/output_file.hpp"

namespace edgewise::atlas {
namespace {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// CSV fields here hold no quotes or line breaks; a comma puts the field in quotes.
std::string csv_field(const std::string& text) {
  return text.find(',') == std::string::npos ? text : "\"" + text + "\"";
}

std::string_view kind_name(ChartKind kind) {
  switch (kind) {
    case ChartKind::bar:
      return "bar";
    case ChartKind::scatter:
      return "scatter";
    case ChartKind::images:
      return "images";
    case ChartKind::line:
      break;
  }
  return "line";
}

}  // namespace

std::string exact_decimal(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

StudyOutput::StudyOutput(std::string study, std::string title, std::string cpu)
    : study_(std::move(study)), title_(std::move(title)), cpu_(std::move(cpu)) {}

void StudyOutput::add_chart(Chart chart) {
  charts_.push_back(std::move(chart));
}

void StudyOutput::set_reading(const std::string& chart, std::string reading) {
  for (Chart& c : charts_) {
    if (c.id == chart) {
      c.reading = std::move(reading);
      return;
    }
  }
  throw std::logic_error("no chart " + chart);
}

void StudyOutput::add(const std::string& chart, const std::string& series, double x, double y) {
  points_.push_back({chart, series, exact_decimal(x), y, ""});
}

void StudyOutput::add(const std::string& chart, const std::string& series, double x, double y,
                      const std::string& label) {
  points_.push_back({chart, series, exact_decimal(x), y, label});
}

void StudyOutput::add(const std::string& chart, const std::string& series,
                      const std::string& category, double y) {
  points_.push_back({chart, series, category, y, ""});
}

void StudyOutput::write(const std::filesystem::path& dir) const {
  const std::filesystem::path csv_path = dir / (study_ + ".csv");
  tools::OutputStream csv(csv_path.string());
  csv << "chart,series,x,y,label\n";
  for (const Point& p : points_) {
    csv << csv_field(p.chart) << ',' << csv_field(p.series) << ',' << csv_field(p.x) << ','
        << exact_decimal(p.y) << ',' << csv_field(p.label) << '\n';
  }
  csv.finish();

  const std::filesystem::path json_path = dir / (study_ + ".json");
  tools::OutputStream json(json_path.string());
  json << "{\n  \"study\": " << json_string(study_) << ",\n  \"title\": " << json_string(title_)
       << ",\n  \"cpu\": " << json_string(cpu_) << ",\n  \"charts\": [";
  for (std::size_t i = 0; i < charts_.size(); ++i) {
    const Chart& c = charts_[i];
    json << (i == 0 ? "\n" : ",\n") << "    {\"id\": " << json_string(c.id)
         << ", \"title\": " << json_string(c.title) << ", \"x_label\": " << json_string(c.x_label)
         << ", \"y_label\": " << json_string(c.y_label)
         << ", \"x_log\": " << (c.x_log ? "true" : "false")
         << ", \"y_log\": " << (c.y_log ? "true" : "false") << ", \"kind\": \"" << kind_name(c.kind)
         << "\", \"reading\": " << json_string(c.reading) << "}";
  }
  json << "\n  ]\n}\n";
  json.finish();
}

}  // namespace edgewise::atlas
