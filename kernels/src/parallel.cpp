// Thread counts and the built-in executor: oneTBB when the library is built with it
// (EDGEWISE_WITH_TBB), otherwise one std::thread per worker for each run.
#include "parallel.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

#include <algorithm>

#if EDGEWISE_HAVE_TBB
#include <map>
#include <memory>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#else
#include <atomic>
#include <exception>
#include <thread>
#include <vector>
#endif

namespace edgewise {
namespace detail {
namespace {

// EDGEWISE_THREADS as a count, or 0 when it is unset or empty.
std::size_t threads_from_environment() {
  const char* value = std::getenv("EDGEWISE_THREADS");
  if (value == nullptr || *value == '\0') return 0;
  const std::string_view text(value);
  std::size_t count = 0;
  for (char c : text) {
    if (c < '0' || c > '9' || count > kMaxThreads) {
      count = kMaxThreads + 1;
      break;
    }
    count = count * 10 + static_cast<std::size_t>(c - '0');
  }
  if (count < 1 || count > kMaxThreads) {
    throw std::invalid_argument("EDGEWISE_THREADS is '" + std::string(text) +
                                "', not a thread count from 1 to " + std::to_string(kMaxThreads));
  }
  return count;
}

#if EDGEWISE_HAVE_TBB
std::size_t builtin_concurrency() {
  return std::min(kMaxThreads, static_cast<std::size_t>(tbb::info::default_concurrency()));
}

// One arena per thread count, made on first use and kept: making one per call costs more than
// a small draw. Arenas may be entered by many threads at once.
tbb::task_arena& arena_for(std::size_t threads) {
  static std::mutex mutex;
  static std::map<std::size_t, std::unique_ptr<tbb::task_arena>> arenas;
  const std::lock_guard lock(mutex);
  std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
  // More slots than oneTBB has workers would only make it print a warning.
  const std::size_t slots = std::min(threads, builtin_concurrency());
  if (!arena) arena = std::make_unique<tbb::task_arena>(static_cast<int>(slots));
  return *arena;
}

void run_builtin(std::size_t threads, std::size_t count,
                 const std::function<void(std::size_t)>& task) {
  arena_for(threads).execute([&] {
    // One task per index: bins differ a lot in work, so each is scheduled on its own.
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
          for (std::size_t i = range.begin(); i != range.end(); ++i)
            task(i);
        },
        tbb::simple_partitioner());
  });
}
#else
std::size_t builtin_concurrency() {
  return std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, kMaxThreads);
}

// Without oneTBB: threads - 1 helpers and the calling thread take indices from one counter.
void run_builtin(std::size_t threads, std::size_t count,
                 const std::function<void(std::size_t)>& task) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
  const auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < count;) {
      try {
        task(i);
      } catch (...) {
        if (!failed.exchange(true)) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> helpers;
  const std::size_t helper_count = std::min(threads, count) - 1;
  helpers.reserve(helper_count);
  for (std::size_t h = 0; h < helper_count; ++h)
    helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers)
    helper.join();
  if (failure) std::rethrow_exception(failure);
}
#endif

}  // namespace

void Workers::run(std::size_t count, const std::function<void(std::size_t)>& task) const {
  if (count == 0) return;
  if (executor != nullptr) {
    (*executor)(count, task);
  } else if (threads == 1 || count == 1) {
    for (std::size_t i = 0; i < count; ++i)
      task(i);
  } else {
    run_builtin(threads, count, task);
  }
}

Workers resolve_workers(std::size_t threads, const TaskExecutor& executor, const char* caller) {
  if (threads > kMaxThreads) {
    throw std::invalid_argument(std::string(caller) + ": threads is " + std::to_string(threads) +
                                ", more than " + std::to_string(kMaxThreads));
  }
  Workers workers;
  workers.threads = threads != 0 ? threads : default_thread_count();
  workers.executor = executor ? &executor : nullptr;
  return workers;
}

}  // namespace detail

std::size_t default_thread_count() {
  const std::size_t from_environment = detail::threads_from_environment();
  return from_environment != 0 ? from_environment : detail::builtin_concurrency();
}

TaskExecutor builtin_executor(std::size_t threads) {
  detail::Workers workers = detail::resolve_workers(threads, {}, "builtin_executor");
  return [workers](std::size_t count, const std::function<void(std::size_t)>& task) {
    workers.run(count, task);
  };
}

}  // namespace edgewise
