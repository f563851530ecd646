// A draw's wall-clock time split by what each thread did (phase_profile.hpp).
#include "phase_profile.hpp"

#include <algorithm>
#include <atomic>
#include <functional>

namespace edgewise::bench {
namespace {

// Each thread's slot in the per-thread times: threads are numbered as they first run a task.
constexpr std::size_t kMaxSlots = 256;
std::size_t thread_slot() {
  static std::atomic<std::size_t> next{0};
  thread_local const std::size_t slot = next.fetch_add(1) % kMaxSlots;
  return slot;
}

}  // namespace

PhaseProfile::PhaseProfile(std::size_t threads)
    : threads_(threads), builtin_(builtin_executor(threads)), per_thread_(kMaxSlots) {}

TaskExecutor PhaseProfile::executor() {
  return [this](std::size_t count, const std::function<void(std::size_t)>& task) {
    for (ThreadTimes& times : per_thread_)
      times.tasks = 0;
    const Clock::time_point start = Clock::now();
    builtin_(count, [&](std::size_t index) {
      ThreadTimes& times = per_thread_[thread_slot()];
      const Clock::time_point begin = Clock::now();
      task(index);
      const Clock::time_point end = Clock::now();
      if (times.tasks++ == 0) times.first_start = begin;
      times.last_end = end;
      times.busy += end - begin;
    });
    add_phase(start, Clock::now());
    tasks_ += count;
  };
}

void PhaseProfile::add_phase(Clock::time_point start, Clock::time_point end) {
  const Clock::duration length = end - start;
  std::size_t threads_seen = 0;
  Clock::duration phase_busy{};
  for (ThreadTimes& times : per_thread_) {
    if (times.tasks == 0) continue;
    ++threads_seen;
    phase_busy += times.busy;
    busy_ += times.busy;
    waking_ += times.first_start - start;
    between_ += (times.last_end - times.first_start) - times.busy;
    tail_ += end - times.last_end;
    times.busy = {};
  }
  // The threads that ran none of the phase's tasks waited through all of it.
  if (threads_seen < threads_) waking_ += length * static_cast<long>(threads_ - threads_seen);
  in_phases_ += length;
  ++phases_;
  if (phase_walls_.size() <= phase_in_draw_) {
    phase_walls_.resize(phase_in_draw_ + 1);
    phase_work_.resize(phase_in_draw_ + 1);
  }
  phase_work_[phase_in_draw_] += phase_busy;
  phase_walls_[phase_in_draw_++] += length;
}

void PhaseProfile::begin_draw() {
  in_phases_ = {};
  phase_in_draw_ = 0;
  draw_start_ = Clock::now();
}

void PhaseProfile::end_draw() {
  const Clock::duration wall = Clock::now() - draw_start_;
  wall_ += wall;
  serial_ += (wall - in_phases_) * static_cast<long>(threads_);
  ++draws_;
}

PhaseProfile::Shares PhaseProfile::shares() const {
  Shares shares;
  if (draws_ == 0 || wall_.count() == 0) return shares;
  const double thread_time = std::chrono::duration<double>(wall_).count() * double(threads_);
  const auto share = [&](Clock::duration d) {
    return std::chrono::duration<double>(d).count() / thread_time;
  };
  shares.serial = share(serial_);
  shares.busy = share(busy_);
  shares.waking = share(waking_);
  shares.between = share(between_);
  shares.tail = share(tail_);
  const double draws = double(draws_);
  shares.work = std::chrono::duration<double>(busy_).count() / draws;
  shares.wall = std::chrono::duration<double>(wall_).count() / draws;
  shares.phases = double(phases_) / draws;
  shares.tasks = double(tasks_) / draws;
  for (Clock::duration phase : phase_walls_)
    shares.phase_walls.push_back(share(phase) * double(threads_));
  for (Clock::duration work : phase_work_)
    shares.phase_work.push_back(std::chrono::duration<double>(work).count() / draws);
  return shares;
}

}  // namespace edgewise::bench
