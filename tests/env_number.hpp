// A test's size or seed from the environment (EDGEWISE_FUZZ_ITERS and the like), so that a slow
// platform (qemu) can run fewer cases and a local soak more, without rebuilding.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>

namespace edgewise::test {

// The number in environment variable `name` (decimal, or 0x hexadecimal), or `fallback` when it
// is unset or empty; a test failure, then `fallback`, when it is not a number.
inline std::uint64_t env_number(const char* name, std::uint64_t fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const std::uint64_t value = std::strtoull(text, &end, 0);
  if (*end != '\0') {
    ADD_FAILURE() << name << "=" << text << " is not a number; using " << fallback;
    return fallback;
  }
  return value;
}

}  // namespace edgewise::test
