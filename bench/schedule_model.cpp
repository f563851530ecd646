// A draw's schedule modelled on many cores (schedule_model.hpp).
#include "schedule_model.hpp"

#include <algorithm>
#include <chrono>
#include <queue>

namespace edgewise::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median_of_five(std::vector<double>& values) {
  std::nth_element(values.begin(), values.begin() + 2, values.end());
  return values[2];
}

}  // namespace

double makespan(const std::vector<double>& tasks, std::size_t workers) {
  std::priority_queue<double, std::vector<double>, std::greater<>> free_at;
  for (std::size_t w = 0; w < workers; ++w)
    free_at.push(0.0);
  double end = 0.0;
  for (double task : tasks) {
    const double finish = free_at.top() + task;
    free_at.pop();
    free_at.push(finish);
    end = std::max(end, finish);
  }
  return end;
}

double median_seconds(const std::function<void()>& prepare, const std::function<void()>& draw) {
  std::vector<double> seconds;
  for (int i = 0; i < 5; ++i) {
    prepare();
    const Clock::time_point start = Clock::now();
    draw();
    seconds.push_back(seconds_since(start));
  }
  return median_of_five(seconds);
}

double modelled_seconds(DrawOptions options, std::size_t threads,
                        const std::function<void()>& prepare,
                        const std::function<void(const DrawOptions&)>& draw,
                        std::vector<double>* phase_work) {
  std::vector<std::vector<double>> phases;
  options.threads = threads;
  options.executor = [&phases](std::size_t count, const std::function<void(std::size_t)>& task) {
    std::vector<double>& times = phases.emplace_back(count);
    for (std::size_t i = 0; i < count; ++i) {
      const Clock::time_point start = Clock::now();
      task(i);
      times[i] = seconds_since(start);
    }
  };
  std::vector<double> seconds, works;
  for (int i = 0; i < 5; ++i) {
    prepare();
    phases.clear();
    const Clock::time_point start = Clock::now();
    draw(options);
    double modelled = seconds_since(start);
    if (works.size() < phases.size()) works.resize(phases.size(), 0.0);
    for (std::size_t p = 0; p < phases.size(); ++p) {
      for (double task : phases[p]) {
        modelled -= task;
        works[p] += task / 5.0;
      }
      modelled += makespan(phases[p], threads);
    }
    seconds.push_back(modelled);
  }
  if (phase_work != nullptr) *phase_work = works;
  return median_of_five(seconds);
}

}  // namespace edgewise::bench
