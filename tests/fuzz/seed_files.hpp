// EDGEWISE_FUZZ_SEEDS=DIR: a fuzz target writes its seed inputs into DIR at start-up, as
// DIR/seed-<name>-<k>, so that a run can start from them (tools/check does).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
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

}  // namespace edgewise::fuzz
