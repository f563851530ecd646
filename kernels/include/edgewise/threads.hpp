// How many threads draw(), count_coverage() and resolve() use, and who runs them.
//
// A call with more than one thread sorts its triangles into screen bins and rasterizes each bin
// on one thread (docs/design/threads.md). Its results (framebuffer, counts, statuses) are
// identical bit for bit to those of one thread, whatever the thread count and the executor.
#pragma once

#include <cstddef>
#include <functional>

namespace edgewise {

// Runs task(0), ..., task(task_count - 1), each exactly once, and returns when all have
// finished. The tasks may run on any threads, in any order, at the same time; they never wait
// for each other. edgewise calls an executor from the thread that called draw() or
// count_coverage(), a few times per call. If a task throws, the executor must still let the
// others finish, then throw; the call passes the exception on, and the target's contents are
// then unspecified.
using TaskExecutor =
    std::function<void(std::size_t task_count, const std::function<void(std::size_t)>& task)>;

// The thread count a call with `threads = 0` uses: the environment variable EDGEWISE_THREADS if
// it is set and not empty, else every core oneTBB can use (its default concurrency; without
// oneTBB, std::thread::hardware_concurrency()). EDGEWISE_THREADS must be a decimal number from 1
// to kMaxThreads, without signs or spaces; anything else throws std::invalid_argument naming
// it. Read at every call.
std::size_t default_thread_count();

// The executor a call uses when it is given none, for `threads` threads (0:
// default_thread_count()): oneTBB's, in one arena per thread count, or plain std::threads in a
// build without oneTBB. For a caller that wraps it, to time or trace the tasks of a call that
// otherwise runs as without an executor. Throws std::invalid_argument as draw() does for a bad
// count (or EDGEWISE_THREADS).
TaskExecutor builtin_executor(std::size_t threads = 0);

// The largest thread count a call accepts (larger DrawOptions::threads or
// RasterOptions::threads throw std::invalid_argument).
inline constexpr std::size_t kMaxThreads = 1024;

}  // namespace edgewise
