// edgewise-sample's binary files: the query records it reads and the RGBA results it writes (the
// latter through common/output_file.hpp), both raw little-endian float32 without header,
// streamed a chunk at a time so that memory stays bounded whatever the file size.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <string>

#include "edgewise/sample.hpp"
#include "edgewise/vector.hpp"

namespace edgewise::sample_tool {

inline constexpr std::size_t kQueryRecordBytes = 6 * sizeof(float);
inline constexpr std::size_t kResultRecordBytes = 4 * sizeof(float);

// Reads queries in order, from a regular file or a pipe (streamed: memory stays bounded). A
// regular file whose size is not a whole number of records is refused when opened, a pipe when
// its end leaves part of a record; anything else (a device such as /dev/zero, which would never
// end) is refused when opened.
class QueryReader {
 public:
  // Throws std::runtime_error("PATH: reason") when the file cannot be opened or read.
  explicit QueryReader(std::string path);
  ~QueryReader();
  QueryReader(const QueryReader&) = delete;
  QueryReader& operator=(const QueryReader&) = delete;

  // The number of queries, when the file's size is known up front.
  std::optional<std::uint64_t> count() const { return count_; }
  // Fills `chunk` from the start; returns how many queries it holds (0 at the end of the file).
  std::size_t read(std::span<TextureQuery> chunk);

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::optional<std::uint64_t> count_;
};

}  // namespace edgewise::sample_tool
