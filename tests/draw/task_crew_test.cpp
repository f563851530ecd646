// The crew that runs a draw's phases (kernels/core/task_crew.hpp): every task of a phase runs
// exactly once, phase after phase, whether the helpers are awake, asleep or never start; the
// first exception a task throws comes back to the caller once every task has finished; a second
// caller is refused rather than mixed in; helpers are started only when missing. Run under
// ThreadSanitizer by tools/check (the suite's name holds "Threads").
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/task_crew.hpp"

namespace edgewise::test::task_crew {
namespace {

using detail::TaskCrew;

// Helpers on threads of their own, as the build without oneTBB starts them.
TaskCrew::Launch on_new_threads() {
  return [](std::function<void()> helper) { std::thread(std::move(helper)).detach(); };
}

// Runs `count` tasks that each count their index, and checks each ran once.
void expect_each_task_once(TaskCrew& crew, std::size_t count) {
  std::vector<std::atomic<int>> runs(count);
  ASSERT_TRUE(crew.run(count, [&](std::size_t i) { runs[i].fetch_add(1); }));
  for (std::size_t i = 0; i < count; ++i)
    ASSERT_EQ(runs[i].load(), 1) << "task " << i << " of " << count;
}

TEST(TaskCrewThreads, EveryTaskRunsOnceInEveryPhase) {
  TaskCrew crew(3, on_new_threads());
  for (std::size_t count = 0; count < 300; count += 1 + count / 8)
    expect_each_task_once(crew, count);
}

TEST(TaskCrewThreads, PhasesAfterTheHelpersLeftStillRunEveryTask) {
  TaskCrew crew(3, on_new_threads());
  for (int phase = 0; phase < 4; ++phase) {
    expect_each_task_once(crew, 64);
    std::this_thread::sleep_for(4 * TaskCrew::kLinger);
  }
}

TEST(TaskCrewThreads, TheCallerRunsEverythingWhenNoHelperStarts) {
  // The crew outlives the helper functions it launched (its destructor waits for them to go).
  std::optional<TaskCrew> crew;
  std::vector<std::function<void()>> never_started;
  crew.emplace(5, [&](std::function<void()> helper) { never_started.push_back(helper); });
  std::vector<std::thread::id> ran_on(100);
  ASSERT_TRUE(
      crew->run(ran_on.size(), [&](std::size_t i) { ran_on[i] = std::this_thread::get_id(); }));
  for (const std::thread::id id : ran_on)
    EXPECT_EQ(id, std::this_thread::get_id());
  // The helpers started once, not once per phase.
  EXPECT_EQ(never_started.size(), 5u);
  crew->call_up();
  expect_each_task_once(*crew, 10);
  EXPECT_EQ(never_started.size(), 5u);
}

TEST(TaskCrewThreads, DestroyingTheCrewWaitsForItsHelpersToLeave) {
  std::atomic<int> inside{0}, left{0};
  {
    TaskCrew crew(3, [&](std::function<void()> helper) {
      std::thread([&, helper] {
        inside.fetch_add(1);
        helper();
        left.fetch_add(1);
      }).detach();
    });
    expect_each_task_once(crew, 50);
  }
  // Every helper function has returned (and been destroyed) by the time the destructor returns.
  EXPECT_EQ(left.load(), inside.load());
}

TEST(TaskCrewThreads, TheFirstExceptionComesBackAfterEveryTaskFinished) {
  TaskCrew crew(3, on_new_threads());
  std::atomic<int> finished{0};
  const auto failing = [&](std::size_t i) {
    std::this_thread::sleep_for(std::chrono::microseconds(50));
    finished.fetch_add(1);
    if (i % 7 == 3) throw std::runtime_error("task failed");
  };
  EXPECT_THROW(crew.run(40, failing), std::runtime_error);
  EXPECT_EQ(finished.load(), 40);
  // The crew is whole again.
  expect_each_task_once(crew, 40);
}

TEST(TaskCrewThreads, ASecondCallerIsRefusedNotMixedIn) {
  TaskCrew crew(2, on_new_threads());
  std::atomic<bool> inside{false}, release{false};
  std::thread first([&] {
    crew.run(1, [&](std::size_t) {
      inside = true;
      while (!release)
        std::this_thread::yield();
    });
  });
  while (!inside)
    std::this_thread::yield();
  bool ran = false;
  EXPECT_FALSE(crew.run(4, [&](std::size_t) { ran = true; }));
  EXPECT_FALSE(ran);
  release = true;
  first.join();
  expect_each_task_once(crew, 4);
}

TEST(TaskCrewThreads, TooManyTasksAreRefused) {
  TaskCrew crew(1, on_new_threads());
  EXPECT_FALSE(crew.run(TaskCrew::kMaxTasks + 1, [](std::size_t) {}));
}

TEST(TaskCrewThreads, CallersTakingTurnsFromSeveralThreadsRunEveryTask) {
  TaskCrew crew(3, on_new_threads());
  std::atomic<std::size_t> total{0}, refused{0};
  std::vector<std::thread> callers;
  for (int c = 0; c < 3; ++c) {
    callers.emplace_back([&] {
      for (int phase = 0; phase < 200; ++phase) {
        std::atomic<std::size_t> ran{0};
        if (crew.run(17, [&](std::size_t) { ran.fetch_add(1); })) {
          EXPECT_EQ(ran.load(), 17u);
          total.fetch_add(ran.load());
        } else {
          EXPECT_EQ(ran.load(), 0u);
          refused.fetch_add(1);
        }
      }
    });
  }
  for (std::thread& caller : callers)
    caller.join();
  EXPECT_EQ(total.load() + 17 * refused.load(), 3u * 200u * 17u);
}

}  // namespace
}  // namespace edgewise::test::task_crew
