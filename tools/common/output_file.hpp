// Writing a tool's output file so that no failure goes unreported: every write, the flush to the
// device and the close are checked, and a failure is an error naming the path and the system's
// reason ("out.png: cannot write: No space left on device"). A disk that fills up, a read-only
// file system or /dev/full all end in that error, never in a truncated file and exit status 0.
//
// Until finish() succeeds the file is incomplete: if the OutputFile is destroyed first (an error
// on the way), a regular file it created or truncated is removed, so that no partial result is
// left looking like a whole one. Devices and pipes (/dev/stdout) are written but never removed.
#pragma once

#include <cstddef>
#include <exception>
#include <ostream>
#include <span>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

namespace edgewise::tools {

class OutputFile {
 public:
  // Opens (creating or truncating) `path` for writing; throws std::runtime_error("PATH: cannot
  // write: reason") when it cannot be opened.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Writes all of `bytes` (retrying short writes); throws as above on any error.
  void write(std::span<const std::byte> bytes);
  void write(std::string_view text);
  // Flushes a regular file to its device (where a full disk may only show now) and closes it;
  // throws as above on any error, after removing the incomplete file.
  void finish();

  const std::string& path() const { return path_; }

 private:
  [[noreturn]] void fail(int error);

  std::string path_;
  int descriptor_ = -1;
  bool regular_file_ = false;
};

// An std::ostream onto an OutputFile, for text written piece by piece (CSV, JSON, listings).
// The stream buffers 64 KiB at a time; the first failed write puts the stream in the bad state,
// and finish() throws it (or any other error on the way) as OutputFile does.
class OutputStream : public std::ostream {
 public:
  explicit OutputStream(std::string path);
  void finish();

 private:
  class Buffer : public std::streambuf {
   public:
    explicit Buffer(std::string path);
    void finish();
    const std::string& path() const { return file_.path(); }

   protected:
    int_type overflow(int_type c) override;
    int sync() override;

   private:
    bool drain();

    OutputFile file_;
    std::vector<char> buffer_;
    std::exception_ptr failure_;
  };
  Buffer buffer_;
};

// The whole of `contents` to `path` through an OutputFile.
void write_whole_file(const std::string& path, std::span<const std::byte> contents);
void write_whole_file(const std::string& path, std::string_view contents);

}  // namespace edgewise::tools
