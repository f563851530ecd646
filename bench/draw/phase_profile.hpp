// Where a draw's wall-clock time goes on many threads: an executor that wraps the built-in one
// and times every task on the thread that runs it, so that each thread's share of the draw's
// time is told apart as serial (the calling thread alone, outside the draw's tasks), busy (in a
// task), waking (a phase begun and the thread not yet in its first task), between (from one of
// its tasks to the next: the scheduler's hand-offs) and tail (its last task done, the phase not).
// The shares are of threads x wall-clock time and add up to 1; they tell a schedule's loss
// (waking, tail) from a loss in the work itself (busy over the one-thread time: what binning
// adds, and what the cores slow each other down by). bench/README.md.
#pragma once

#include <chrono>
#include <cstddef>
#include <vector>

#include "edgewise/edgewise.hpp"

namespace edgewise::bench {

class PhaseProfile {
 public:
  // Profiles `threads` threads (the executor's count; threads that ran no task of a phase were
  // idle through it).
  explicit PhaseProfile(std::size_t threads);

  // The built-in executor for the profile's threads, timed.
  TaskExecutor executor();

  // Brackets one draw() call; between them, the executor's phases are added to the totals.
  void begin_draw();
  void end_draw();

  struct Shares {
    double serial = 0, busy = 0, waking = 0, between = 0, tail = 0;
    double work = 0;                  // seconds per draw in tasks, all threads together
    double wall = 0;                  // seconds per draw
    double phases = 0;                // executor calls per draw
    double tasks = 0;                 // tasks per draw
    std::vector<double> phase_walls;  // each phase's wall-clock share, in draw order
    std::vector<double> phase_work;   // each phase's seconds in tasks per draw, all threads
  };
  // The totals over the draws bracketed so far, per draw.
  Shares shares() const;

 private:
  using Clock = std::chrono::steady_clock;
  struct alignas(64) ThreadTimes {  // a cache line each: threads write their own
    Clock::time_point first_start, last_end;
    Clock::duration busy{};
    std::size_t tasks = 0;
  };
  void add_phase(Clock::time_point start, Clock::time_point end);

  std::size_t threads_;
  TaskExecutor builtin_;
  std::vector<ThreadTimes> per_thread_;  // of the phase being run, by thread slot
  Clock::time_point draw_start_;
  Clock::duration in_phases_{}, serial_{}, busy_{}, waking_{}, between_{}, tail_{}, wall_{};
  std::vector<Clock::duration> phase_walls_, phase_work_;  // by the phase's place in its draw
  std::size_t draws_ = 0, phases_ = 0, tasks_ = 0, phase_in_draw_ = 0;
};

}  // namespace edgewise::bench
