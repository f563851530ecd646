#include "common/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace edgewise::tools {

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  do {
    descriptor_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOCTTY, 0666);
  } while (descriptor_ < 0 && errno == EINTR);
  if (descriptor_ < 0) fail(errno);
  struct stat status {};
  regular_file_ = ::fstat(descriptor_, &status) == 0 && S_ISREG(status.st_mode);
}

OutputFile::~OutputFile() {
  if (descriptor_ < 0) return;  // finished, or failed and cleaned up
  ::close(descriptor_);
  if (regular_file_) std::remove(path_.c_str());
}

void OutputFile::fail(int error) {
  if (descriptor_ >= 0) {
    ::close(std::exchange(descriptor_, -1));
    if (regular_file_) std::remove(path_.c_str());
  }
  throw std::runtime_error(path_ + ": cannot write: " + std::strerror(error));
}

void OutputFile::write(std::span<const std::byte> bytes) {
  if (descriptor_ < 0) throw std::logic_error("OutputFile::write after finish");
  while (!bytes.empty()) {
    const ssize_t written = ::write(descriptor_, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      fail(errno);
    }
    // write() returns 0 for a non-empty buffer only on a device that takes nothing more.
    if (written == 0) fail(ENOSPC);
    bytes = bytes.subspan(static_cast<std::size_t>(written));
  }
}

void OutputFile::write(std::string_view text) {
  write(std::as_bytes(std::span<const char>(text.data(), text.size())));
}

void OutputFile::finish() {
  if (descriptor_ < 0) throw std::logic_error("OutputFile::finish twice");
  // A file system may accept writes into its cache and only fail when they reach the disk.
  if (regular_file_ && ::fsync(descriptor_) != 0) fail(errno);
  // close() reports deferred errors (NFS, quotas); its descriptor is gone either way, so no
  // retry on EINTR.
  if (::close(descriptor_) != 0) {
    descriptor_ = -1;
    const int error = errno;
    if (regular_file_) std::remove(path_.c_str());
    throw std::runtime_error(path_ + ": cannot write: " + std::strerror(error));
  }
  descriptor_ = -1;
}

OutputStream::Buffer::Buffer(std::string path) : file_(std::move(path)), buffer_(1 << 16) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
}

bool OutputStream::Buffer::drain() {
  if (failure_) return false;
  try {
    file_.write(
        std::as_bytes(std::span<const char>(pbase(), static_cast<std::size_t>(pptr() - pbase()))));
  } catch (...) {
    failure_ = std::current_exception();
    return false;
  }
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return true;
}

OutputStream::Buffer::int_type OutputStream::Buffer::overflow(int_type c) {
  if (!drain()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int OutputStream::Buffer::sync() {
  return drain() ? 0 : -1;
}

void OutputStream::Buffer::finish() {
  drain();
  if (failure_) std::rethrow_exception(failure_);
  file_.finish();
}

OutputStream::OutputStream(std::string path) : std::ostream(nullptr), buffer_(std::move(path)) {
  rdbuf(&buffer_);
}

void OutputStream::finish() {
  buffer_.finish();
  // The buffer reports its own failures; anything else (a formatting error) is the stream's.
  if (fail()) throw std::runtime_error(buffer_.path() + ": cannot write: the stream failed");
}

void write_whole_file(const std::string& path, std::span<const std::byte> contents) {
  OutputFile file(path);
  file.write(contents);
  file.finish();
}

void write_whole_file(const std::string& path, std::string_view contents) {
  OutputFile file(path);
  file.write(contents);
  file.finish();
}

}  // namespace edgewise::tools
