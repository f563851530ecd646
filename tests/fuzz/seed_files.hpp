// EDGEWISE_FUZZ_SEEDS=DIR: a fuzz target writes its seed inputs into DIR at start-up, as
// DIR/seed-<name>-<k>, so that a run can start from them (tools/check does).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <vector>

namespace edgewise::fuzz {

inline void write_seed_files(const char* target, const char* name,
                             const std::vector<std::vector<std::uint8_t>>& seeds) {
  const char* directory = std::getenv("EDGEWISE_FUZZ_SEEDS");
  if (directory == nullptr || directory[0] == '\0') return;
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const std::string path = std::string(directory) + "/seed-" + name + "-" + std::to_string(k);
    if (std::FILE* file = std::fopen(path.c_str(), "wb")) {
      std::fwrite(seeds[k].data(), 1, seeds[k].size(), file);
      std::fclose(file);
    } else {
      std::fprintf(stderr, "%s: cannot write %s\n", target, path.c_str());
    }
  }
}

// Builds a seed input in the encoding the targets' decoders share: bytes, and numbers as tag 0
// and an int16 in units of 1/4096 when that is exact, else tag 255 and the float's four bytes.
// Derived adds its target's own records; the calls chain.
template <class Derived>
class SeedWriter {
 public:
  Derived& u8(std::uint32_t v) {
    bytes.push_back(static_cast<std::uint8_t>(v));
    return self();
  }
  Derived& i8(std::int32_t v) { return u8(static_cast<std::uint32_t>(v) & 0xFF); }
  Derived& number(float v) {
    const float fixed = v * 4096.0f;
    if (fixed == std::nearbyint(fixed) && fixed >= -32768.0f && fixed <= 32767.0f) {
      const std::uint32_t bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(fixed));
      return u8(0).u8(bits & 0xFF).u8((bits >> 8) & 0xFF);
    }
    u8(255);
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
    for (int i = 0; i < 4; ++i)
      u8((bits >> (8 * i)) & 0xFF);
    return self();
  }
  Derived& numbers(std::initializer_list<float> values) {
    for (float v : values)
      number(v);
    return self();
  }

  std::vector<std::uint8_t> bytes;

 private:
  Derived& self() { return static_cast<Derived&>(*this); }
};

}  // namespace edgewise::fuzz
