#include "common/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace edgewise::tools {

Progress::Progress(std::string label, std::int64_t total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      enabled_(::isatty(::fileno(stderr)) == 1) {}

Progress::~Progress() {
  if (shown_ && !finished_) std::fputc('\n', stderr);
}

void Progress::update(std::int64_t done) {
  if (!enabled_ || finished_) return;
  std::fprintf(stderr, "\r%s: %lld/%lld %s", label_.c_str(), static_cast<long long>(done),
               static_cast<long long>(total_), unit_.c_str());
  std::fflush(stderr);
  shown_ = true;
}

void Progress::finish() {
  if (finished_) return;
  update(total_);
  if (shown_) std::fputc('\n', stderr);
  finished_ = true;
}

}  // namespace edgewise::tools
