// Output directories are checked before any work: a run that computes for minutes should not
// fail at its first write.
#pragma once

#include <filesystem>

namespace edgewise::texture_quality {

// Creates the directory (and its parents) if needed and checks that a file can be created in
// it. Throws std::runtime_error("DIR: cannot write: reason").
void prepare_writable_directory(const std::filesystem::path& directory);

}  // namespace edgewise::texture_quality
