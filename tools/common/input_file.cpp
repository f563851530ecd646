#include "common/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace edgewise::tools {
namespace {

const char* kind_of(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a pipe";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

[[noreturn]] void refuse(const std::string& path, const std::string& reason) {
  throw std::runtime_error(path + ": cannot open: " + reason);
}

}  // namespace

std::uint64_t require_regular_file(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) refuse(path, std::strerror(errno));
  if (S_ISDIR(status.st_mode)) refuse(path, std::strerror(EISDIR));
  if (!S_ISREG(status.st_mode)) {
    refuse(path, std::string("not a regular file (") + kind_of(status.st_mode) + ")");
  }
  // Permission is the opener's question, not the mode bits' (root, ACLs).
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (descriptor < 0) refuse(path, std::strerror(errno));
  ::close(descriptor);
  return static_cast<std::uint64_t>(status.st_size);
}

}  // namespace edgewise::tools
