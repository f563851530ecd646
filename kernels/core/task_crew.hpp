// A crew of helper threads that stays with its caller from one phase of tasks to the next
// (docs/design/threads.md). A draw runs a few short phases one after the other (vertex
// ranges, triangle ranges, bins), each a few hundred microseconds on many cores: a pool whose
// threads go to sleep after every phase and are woken for the next pays a wake-up per phase,
// and on a virtual machine a wake-up can take as long as the phase. The crew's helpers wait by
// spinning for kLinger after the last task they found, so that a draw's phases find them
// awake; a draw calls them up at its start, so that they wake while it prepares its first phase.
// Tasks are dealt in index order, each to whichever thread asks first, from one counter.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>

namespace edgewise::detail {

class TaskCrew {
 public:
  // Starts one helper: runs the function it is given on some other thread, soon.
  using Launch = std::function<void(std::function<void()>)>;
  // How long a helper keeps waiting, spinning, for the next phase after its last task.
  static constexpr std::chrono::microseconds kLinger{200};
  // Phases of more tasks than this are not the crew's (run() returns false).
  static constexpr std::size_t kMaxTasks = (std::size_t{1} << 20) - 1;

  // A crew of `helpers` helpers besides the caller, started by `launch` when needed.
  TaskCrew(std::size_t helpers, Launch launch);
  // Sends the helpers away and waits until every function `launch` was given has been
  // destroyed (a helper that has not started yet starts, sees the crew closing and returns).
  ~TaskCrew();
  TaskCrew(const TaskCrew&) = delete;
  TaskCrew& operator=(const TaskCrew&) = delete;

  // Starts the helpers that have left (none when all wait), and returns at once.
  void call_up();

  // Runs task(0) .. task(count - 1) on the calling thread and the helpers, returning when all
  // have finished; rethrows the first exception a task threw, after all have finished. Returns
  // false, running nothing, when another thread holds the crew or count exceeds kMaxTasks: the
  // caller then runs the tasks some other way.
  bool run(std::size_t count, const std::function<void(std::size_t)>& task);

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;  // also held by every helper, which may outlive the crew
  std::size_t helpers_;
  Launch launch_;
  std::mutex caller_;
};

}  // namespace edgewise::detail
