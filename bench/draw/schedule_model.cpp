// A draw's schedule modelled on many cores (schedule_model.hpp).
#include "schedule_model.hpp"

#include <algorithm>
#include <chrono>
#include <queue>
#include <span>

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
                        std::vector<double>* phase_work, double* serial) {
  // Each phase's task times; the storage is kept from run to run, so that the calling thread's
  // time outside the tasks has no allocation of the model's in it once warm.
  // The calling thread's time outside them is the draw's time less its executor calls' (the
  // timing's own cost between tasks belongs to no schedule: neither serial nor a task).
  std::vector<std::vector<double>> storage;
  std::size_t phase_count = 0;
  double in_phases = 0.0;
  options.threads = threads;
  options.executor = [&](std::size_t count, const std::function<void(std::size_t)>& task) {
    const Clock::time_point phase_start = Clock::now();
    if (phase_count == storage.size()) storage.emplace_back();
    std::vector<double>& times = storage[phase_count++];
    times.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const Clock::time_point start = Clock::now();
      task(i);
      times[i] = seconds_since(start);
    }
    in_phases += seconds_since(phase_start);
  };
  std::vector<double> seconds, serials, works;
  for (int i = 0; i < 6; ++i) {  // the first run warms the storage and is not counted
    prepare();
    phase_count = 0;
    in_phases = 0.0;
    const Clock::time_point start = Clock::now();
    draw(options);
    double modelled = seconds_since(start) - in_phases;
    if (i == 0) continue;
    const std::span<const std::vector<double>> phases(storage.data(), phase_count);
    if (works.size() < phases.size()) works.resize(phases.size(), 0.0);
    for (std::size_t p = 0; p < phases.size(); ++p) {
      for (double task : phases[p])
        works[p] += task / 5.0;
    }
    serials.push_back(modelled);
    for (const std::vector<double>& phase : phases)
      modelled += makespan(phase, threads);
    seconds.push_back(modelled);
  }
  if (phase_work != nullptr) *phase_work = works;
  if (serial != nullptr) *serial = median_of_five(serials);
  return median_of_five(seconds);
}

}  // namespace edgewise::bench
