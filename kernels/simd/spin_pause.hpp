// A spin-wait hint to the processor: on x86, `pause` (the other hardware thread of the core runs,
// and leaving the loop does not flush the pipeline); on AArch64, `yield`; elsewhere the thread
// gives up the processor.
#pragma once

#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace edgewise::detail {

inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#else
  std::this_thread::yield();
#endif
}

}  // namespace edgewise::detail
