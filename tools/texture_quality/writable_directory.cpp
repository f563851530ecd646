#include "texture_quality/writable_directory.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace edgewise::texture_quality {

void prepare_writable_directory(const std::filesystem::path& directory) {
  const auto cannot_write = [&directory](const std::string& reason) {
    return std::runtime_error(directory.string() + ": cannot write: " + reason);
  };
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw cannot_write(error.message());
  if (!std::filesystem::is_directory(directory)) throw cannot_write("not a directory");
  // Permissions alone do not tell (a read-only file system, running as root): create a file.
  const std::filesystem::path probe = directory / (".write-test-" + std::to_string(::getpid()));
  {
    std::ofstream file(probe);
    if (!file) throw cannot_write(std::strerror(errno));
  }
  std::filesystem::remove(probe, error);
}

}  // namespace edgewise::texture_quality
