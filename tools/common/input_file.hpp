// Checks on a file a tool is asked to read, before anything reads it: it must be a regular file
// that this process can open. Devices, pipes and sockets are refused because a read of them may
// never end (/dev/zero, /dev/urandom, a FIFO with no writer) or may consume what another
// program needs; a directory or a missing file gets the system's own reason.
#pragma once

#include <cstdint>
#include <string>

namespace edgewise::tools {

// The size of the regular file at `path` (symbolic links followed). Throws
// std::runtime_error("PATH: cannot open: reason") when it is missing, unreadable, a directory or
// not a regular file ("not a regular file (a character device)").
std::uint64_t require_regular_file(const std::string& path);

}  // namespace edgewise::tools
