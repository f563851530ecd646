// A draw's schedule on many cores, measured on few: the draw is made for `threads` threads (its
// ranges, bins and sub-bins), its tasks are run one after the other on the calling thread and
// timed, and every phase (one executor call) then takes its makespan() on `threads` workers,
// added to the calling thread's time outside the tasks. What the cores would share (memory
// bandwidth, the last-level cache) is not in it: it models the schedule (serial parts, task
// counts, balance), as Amdahl's bound models the serial share (bench/README.md).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "edgewise/edgewise.hpp"

namespace edgewise::bench {

// The time `tasks` (seconds each) take when dealt, in order, each to whichever of `workers`
// workers is free first: how a dynamic scheduler spreads them.
double makespan(const std::vector<double>& tasks, std::size_t workers);

// The median over five runs of `draw` (each after `prepare`, which is not timed), in seconds.
double median_seconds(const std::function<void()>& prepare, const std::function<void()>& draw);

// The modelled time of `draw` with `options` made for `threads` threads: the median of five.
// `phase_work`, when given, receives each phase's tasks' time added up, in seconds (the mean
// over the five runs), phases in the order the draw runs them; `serial`, when given, the calling
// thread's time outside the tasks (the median of the five).
double modelled_seconds(DrawOptions options, std::size_t threads,
                        const std::function<void()>& prepare,
                        const std::function<void(const DrawOptions&)>& draw,
                        std::vector<double>* phase_work = nullptr, double* serial = nullptr);

}  // namespace edgewise::bench
