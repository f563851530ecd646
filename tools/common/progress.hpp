// Progress of long work (a ground truth takes minutes) on standard error, when standard error is
// a terminal: one line rewritten in place, "\rground truth: 96/270 rows", ended by a newline when
// the work is done. Elsewhere (a file, a pipe, a test) it prints nothing, so logs and the tools'
// outputs stay as they are.
#pragma once

#include <cstdint>
#include <string>

namespace edgewise::tools {

class Progress {
 public:
  // `label` says what is done ("ground truth"), `unit` what is counted ("rows"), out of `total`.
  Progress(std::string label, std::int64_t total, std::string unit);
  // Ends the line if anything was shown (also when the work failed half-way).
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` units of `total` are done.
  void update(std::int64_t done);
  // Shows the total done and ends the line.
  void finish();

 private:
  std::string label_, unit_;
  std::int64_t total_ = 0;
  bool shown_ = false, finished_ = false;
  bool enabled_ = false;
};

}  // namespace edgewise::tools
