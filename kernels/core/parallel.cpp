// Thread counts and the built-in executor: a crew of helper threads (task_crew.hpp), started by
// oneTBB when the library is built with it (EDGEWISE_WITH_TBB), otherwise plain std::threads.
#include "parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>

#include "task_crew.hpp"

#if EDGEWISE_HAVE_TBB
#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#else
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
    throw std::invalid_argument("EDGEWISE_THREADS=" + std::string(text) +
                                ": not a thread count from 1 to " + std::to_string(kMaxThreads));
  }
  return count;
}

#if EDGEWISE_HAVE_TBB
std::size_t builtin_concurrency() {
  return std::min(kMaxThreads, static_cast<std::size_t>(tbb::info::default_concurrency()));
}

// One arena and one crew per thread count, made on first use and kept: making them per call
// costs more than a small draw. Destroyed at exit, the crew first: it waits for its helpers to
// leave the arena.
struct Builtin {
  explicit Builtin(std::size_t slots)
      : arena(static_cast<int>(slots)), crew(slots - 1, [this](std::function<void()> helper) {
          arena.enqueue(std::move(helper));
        }) {
    arena.initialize();
  }
  tbb::task_arena arena;
  TaskCrew crew;
};

Builtin& builtin_for(std::size_t threads) {
  static std::mutex mutex;
  static std::map<std::size_t, std::unique_ptr<Builtin>> builtins;
  const std::lock_guard lock(mutex);
  std::unique_ptr<Builtin>& builtin = builtins[threads];
  // More slots than oneTBB has workers would only make it print a warning.
  if (!builtin) builtin = std::make_unique<Builtin>(std::min(threads, builtin_concurrency()));
  return *builtin;
}

// When another thread holds the crew: the arena's threads, each taking indices in order from
// one counter until none is left.
void run_in_arena(tbb::task_arena& arena, std::size_t count,
                  const std::function<void(std::size_t)>& task) {
  const auto loops =
      std::min<std::size_t>(count, static_cast<std::size_t>(arena.max_concurrency()));
  arena.execute([&] {
    std::atomic<std::size_t> next{0};
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, loops, 1),
        [&](const tbb::blocked_range<std::size_t>&) {
          for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;)
            task(i);
        },
        tbb::simple_partitioner());
  });
}

void run_builtin(std::size_t threads, std::size_t count,
                 const std::function<void(std::size_t)>& task) {
  Builtin& builtin = builtin_for(threads);
  if (!builtin.crew.run(count, task)) run_in_arena(builtin.arena, count, task);
}

void call_up_builtin(std::size_t threads) {
  builtin_for(threads).crew.call_up();
}
#else
std::size_t builtin_concurrency() {
  return std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, kMaxThreads);
}

// Without oneTBB: a crew of plain threads per thread count, made on first use and kept until
// exit, when it waits for its helpers to leave.
TaskCrew& crew_for(std::size_t threads) {
  static std::mutex mutex;
  static std::map<std::size_t, std::unique_ptr<TaskCrew>> crews;
  const std::lock_guard lock(mutex);
  std::unique_ptr<TaskCrew>& crew = crews[threads];
  if (!crew) {
    crew = std::make_unique<TaskCrew>(
        threads - 1, [](std::function<void()> helper) { std::thread(std::move(helper)).detach(); });
  }
  return *crew;
}

// When another thread holds the crew: threads - 1 threads started for this call and the calling
// thread take indices from one counter.
void run_on_new_threads(std::size_t threads, std::size_t count,
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

void run_builtin(std::size_t threads, std::size_t count,
                 const std::function<void(std::size_t)>& task) {
  if (!crew_for(threads).run(count, task)) run_on_new_threads(threads, count, task);
}

void call_up_builtin(std::size_t threads) {
  crew_for(threads).call_up();
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

void Workers::call_up() const {
  if (executor == nullptr && threads > 1) call_up_builtin(threads);
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
