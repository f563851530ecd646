// The threads of one call: how many (threads.hpp's rules applied to its options), and how its
// tasks are run (the caller's executor, else oneTBB, else plain std::threads).
#pragma once

#include <cstddef>
#include <functional>

#include "edgewise/threads.hpp"

namespace edgewise::detail {

struct Workers {
  std::size_t threads = 1;                 // at least 1
  const TaskExecutor* executor = nullptr;  // the caller's, or null for the built-in one

  // Runs task(0) .. task(count - 1) on these workers and returns when all have finished.
  void run(std::size_t count, const std::function<void(std::size_t)>& task) const;
  // Wakes the built-in executor's threads (task_crew.hpp) and returns at once: a call makes
  // it first, so that they wake while it prepares its first run().
  void call_up() const;
};

// `threads` 0 means default_thread_count(); throws std::invalid_argument above kMaxThreads.
Workers resolve_workers(std::size_t threads, const TaskExecutor& executor, const char* caller);

}  // namespace edgewise::detail
