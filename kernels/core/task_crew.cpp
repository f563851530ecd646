// A crew of helper threads kept awake between phases (task_crew.hpp).
//
// The phase being run is one 64-bit word: its generation, its task count and the next index to
// take. A thread takes an index by a compare-and-swap of the whole word, so that a helper still
// holding a word of an earlier phase can never take an index of a later one; and a phase's tasks
// (the function and the finished count, on the caller's stack) are read only after an index of
// that phase has been taken, which keeps the caller waiting until the task is done.
#include "task_crew.hpp"

#include <exception>
#include <thread>

#include "../simd/spin_pause.hpp"

namespace edgewise::detail {
namespace {

constexpr int kIndexBits = 20;
constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << kIndexBits) - 1;

constexpr std::uint64_t make_word(std::uint64_t generation, std::uint64_t count,
                                  std::uint64_t next) {
  return (generation << (2 * kIndexBits)) | (count << kIndexBits) | next;
}
constexpr std::size_t count_of(std::uint64_t word) {
  return static_cast<std::size_t>((word >> kIndexBits) & kIndexMask);
}
constexpr std::size_t next_of(std::uint64_t word) {
  return static_cast<std::size_t>(word & kIndexMask);
}

// The `waits`-th wait in a row of a spin loop: a pause (spin_pause), which lets the other hardware
// thread of the core run, for the first kSpinsBeforeYield; then the processor itself, so that on a
// machine with more threads than cores (or a busy one) the thread that holds a task can run.
constexpr unsigned kSpinsBeforeYield = 64;
inline void wait_a_little(unsigned waits) {
  if (waits > kSpinsBeforeYield) {
    std::this_thread::yield();
    return;
  }
  spin_pause();
}

}  // namespace

struct TaskCrew::Shared {
  struct Phase {
    const std::function<void(std::size_t)>* task = nullptr;
    std::atomic<std::size_t> finished{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;
  };
  std::atomic<std::uint64_t> word{0};
  std::atomic<Phase*> phase{nullptr};
  std::atomic<std::size_t> helpers{0};  // started and not yet gone
  std::atomic<bool> closing{false};     // the crew is being destroyed: helpers leave
  std::atomic<std::size_t> handles{0};  // helper functions launched and not yet destroyed

  // Takes the next index of the phase in `word` and runs it; false when none is left.
  bool take_one(std::uint64_t word_seen) {
    if (next_of(word_seen) >= count_of(word_seen)) return false;
    if (!word.compare_exchange_weak(word_seen, word_seen + 1, std::memory_order_acquire,
                                    std::memory_order_relaxed)) {
      return true;  // another thread took it: look again
    }
    Phase& current = *phase.load(std::memory_order_relaxed);
    try {
      (*current.task)(next_of(word_seen));
    } catch (...) {
      if (!current.failed.exchange(true)) current.failure = std::current_exception();
    }
    current.finished.fetch_add(1, std::memory_order_release);
    return true;
  }

  void help() {
    using Clock = std::chrono::steady_clock;
    Clock::time_point until = Clock::now() + kLinger;
    for (unsigned waits = 0;;) {
      if (take_one(word.load(std::memory_order_acquire))) {
        until = Clock::time_point{};
        waits = 0;
        continue;
      }
      wait_a_little(++waits);
      if (waits % 64 != 0) continue;
      if (closing.load(std::memory_order_acquire)) {
        helpers.fetch_sub(1, std::memory_order_acq_rel);
        return;
      }
      const Clock::time_point now = Clock::now();
      if (until == Clock::time_point{}) until = now + kLinger;
      if (now < until) continue;
      helpers.fetch_sub(1, std::memory_order_acq_rel);
      // A phase begun just now may have counted on this helper: stay for it.
      const std::uint64_t last = word.load(std::memory_order_acquire);
      if (next_of(last) >= count_of(last)) return;
      helpers.fetch_add(1, std::memory_order_acq_rel);
      until = Clock::time_point{};
    }
  }
};

namespace {

// A helper's hold on the crew's shared state, counted in Shared::handles for as long as any copy
// of it lives (a launched function may be copied before it runs), so that the crew's destructor
// can wait until no helper function is left.
template <class Shared>
class HelperHandle {
 public:
  explicit HelperHandle(std::shared_ptr<Shared> shared) : shared_(std::move(shared)) {
    shared_->handles.fetch_add(1, std::memory_order_acq_rel);
  }
  HelperHandle(const HelperHandle& other) : HelperHandle(other.shared_) {}
  HelperHandle& operator=(const HelperHandle&) = delete;
  ~HelperHandle() { shared_->handles.fetch_sub(1, std::memory_order_acq_rel); }
  Shared& operator*() const { return *shared_; }

 private:
  std::shared_ptr<Shared> shared_;
};

}  // namespace

TaskCrew::TaskCrew(std::size_t helpers, Launch launch)
    : shared_(std::make_shared<Shared>()), helpers_(helpers), launch_(std::move(launch)) {}

TaskCrew::~TaskCrew() {
  shared_->closing.store(true, std::memory_order_release);
  while (shared_->handles.load(std::memory_order_acquire) != 0)
    std::this_thread::yield();
}

void TaskCrew::call_up() {
  std::size_t present = shared_->helpers.load(std::memory_order_acquire);
  while (present < helpers_) {
    if (!shared_->helpers.compare_exchange_weak(present, present + 1, std::memory_order_acq_rel)) {
      continue;
    }
    launch_([handle = HelperHandle<Shared>(shared_)] {
      Shared& shared = *handle;
      if (shared.closing.load(std::memory_order_acquire)) {
        shared.helpers.fetch_sub(1, std::memory_order_acq_rel);
        return;
      }
      shared.help();
    });
    ++present;
  }
}

bool TaskCrew::run(std::size_t count, const std::function<void(std::size_t)>& task) {
  if (count > kMaxTasks) return false;
  const std::unique_lock lock(caller_, std::try_to_lock);
  if (!lock.owns_lock()) return false;
  call_up();
  Shared& shared = *shared_;
  Shared::Phase phase;
  phase.task = &task;
  shared.phase.store(&phase, std::memory_order_relaxed);
  const std::uint64_t generation =
      (shared.word.load(std::memory_order_relaxed) >> (2 * kIndexBits)) + 1;
  // The generation keeps the word's top bits: it wraps after 2^24 phases.
  shared.word.store(make_word(generation, count, 0), std::memory_order_release);
  while (shared.take_one(shared.word.load(std::memory_order_acquire))) {
  }
  for (unsigned waits = 0; phase.finished.load(std::memory_order_acquire) != count;)
    wait_a_little(++waits);
  if (phase.failed.load(std::memory_order_relaxed)) std::rethrow_exception(phase.failure);
  return true;
}

}  // namespace edgewise::detail
