#include "test_files.hpp"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>

namespace edgewise::sample_cli_test {

void write_image(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type,
                 const void* pixels) {
  OIIO::ImageSpec spec(width, height, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, spec) || !out->write_image(type, pixels) || !out->close()) {
    throw std::runtime_error(path +
                             ": cannot write: " + (out ? out->geterror() : OIIO::geterror()));
  }
}

void write_queries(const std::string& path, std::span<const TextureQuery> queries) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(queries.data()),
            static_cast<std::streamsize>(queries.size_bytes()));
  if (!out) throw std::runtime_error(path + ": cannot write");
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error(path + ": cannot write");
}

std::vector<Vec4> read_results(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes.size() % sizeof(Vec4), 0u) << path;
  std::vector<Vec4> results(bytes.size() / sizeof(Vec4));
  std::copy_n(bytes.data(), results.size() * sizeof(Vec4), reinterpret_cast<char*>(results.data()));
  return results;
}

}  // namespace edgewise::sample_cli_test
