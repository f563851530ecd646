#include "sample/record_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "sample/file_error.hpp"

namespace edgewise::sample_tool {

// The records are the in-memory structs, read and written as they are.
static_assert(std::endian::native == std::endian::little,
              "the query and result files are little-endian; this host is not");
static_assert(sizeof(TextureQuery) == kQueryRecordBytes, "TextureQuery is six packed floats");
static_assert(sizeof(Vec4) == kResultRecordBytes, "Vec4 is four packed floats");

namespace {

std::runtime_error not_whole_records(const std::string& path, std::uint64_t bytes) {
  return std::runtime_error(path + ": " + std::to_string(bytes) +
                            " bytes is not a whole number of 24-byte query records "
                            "(s, t, dsdx, dtdx, dsdy, dtdy as float32)");
}

}  // namespace

QueryReader::QueryReader(std::string path) : path_(std::move(path)) {
  // Opened without waiting for a writer: a pipe that nobody writes to then reads as empty
  // instead of blocking forever.
  const int descriptor = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (descriptor < 0) throw file_error(path_, "cannot open", errno);
  struct stat status {};
  if (::fstat(descriptor, &status) != 0) {
    const int error = errno;
    ::close(descriptor);
    throw file_error(path_, "cannot open", error);
  }
  const auto refuse = [&](std::runtime_error error) {
    ::close(descriptor);
    throw std::move(error);
  };
  if (S_ISDIR(status.st_mode)) refuse(file_error(path_, "cannot open", EISDIR));
  // A device (/dev/zero, /dev/urandom) would never end; a pipe ends when its writer closes it.
  if (!S_ISREG(status.st_mode) && !S_ISFIFO(status.st_mode)) {
    refuse(std::runtime_error(path_ + ": cannot open: not a regular file or a pipe"));
  }
  const int flags = ::fcntl(descriptor, F_GETFL);
  if (flags < 0 || ::fcntl(descriptor, F_SETFL, flags & ~O_NONBLOCK) != 0) {
    refuse(file_error(path_, "cannot open", errno));
  }
  file_ = ::fdopen(descriptor, "rb");
  if (file_ == nullptr) refuse(file_error(path_, "cannot open", errno));
  const auto refuse_file = [&](std::runtime_error error) {
    std::fclose(file_);
    throw std::move(error);
  };
  if (S_ISREG(status.st_mode)) {
    const auto bytes = static_cast<std::uint64_t>(status.st_size);
    if (bytes % kQueryRecordBytes != 0) refuse_file(not_whole_records(path_, bytes));
    count_ = bytes / kQueryRecordBytes;
  }
}

QueryReader::~QueryReader() {
  std::fclose(file_);
}

std::size_t QueryReader::read(std::span<TextureQuery> chunk) {
  // fread returns short only at the end of the file or on an error.
  const std::size_t bytes = std::fread(chunk.data(), 1, chunk.size_bytes(), file_);
  if (std::ferror(file_)) throw file_error(path_, "cannot read", errno);
  if (bytes % kQueryRecordBytes != 0) {
    const std::size_t left_over = bytes % kQueryRecordBytes;
    throw std::runtime_error(path_ + ": ends inside a query record (" + std::to_string(left_over) +
                             (left_over == 1 ? " byte" : " bytes") +
                             " left over; records are 24 bytes)");
  }
  return bytes / kQueryRecordBytes;
}

}  // namespace edgewise::sample_tool
