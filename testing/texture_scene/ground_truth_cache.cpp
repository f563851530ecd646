#include "texture_scene/ground_truth_cache.hpp"

#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace edgewise::texture_scene {
namespace {

// The file is the in-memory representation of each field, which is little-endian here.
static_assert(std::endian::native == std::endian::little, "ground-truth files are little-endian");

constexpr char kMagic[8] = {'E', 'W', 'G', 'T', 'R', 'U', 'T', 'H'};
constexpr std::uint32_t kFormatVersion = 1;
// Bump when ground_truth()'s results change for the same inputs, to invalidate old files.
constexpr std::uint64_t kEvaluatorVersion = 1;

class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
      hash_ = (hash_ ^ p[i]) * 0x100000001b3ull;
  }
  template <typename T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  std::uint64_t hash() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

class Writer {
 public:
  template <typename T>
  void value(const T& v) {
    append(&v, sizeof v);
  }
  void append(const void* data, std::size_t size) {
    const auto* p = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class Reader {
 public:
  explicit Reader(std::vector<char> bytes) : bytes_(std::move(bytes)) {}
  // False (and nothing read) when fewer than `size` bytes are left.
  bool take(void* data, std::size_t size) {
    if (bytes_.size() - position_ < size) return false;
    std::memcpy(data, bytes_.data() + position_, size);
    position_ += size;
    return true;
  }
  template <typename T>
  bool value(T& v) {
    return take(&v, sizeof v);
  }
  bool at_end() const { return position_ == bytes_.size(); }

 private:
  std::vector<char> bytes_;
  std::size_t position_ = 0;
};

}  // namespace

std::uint64_t ground_truth_fingerprint(const LinearImage& texture, WrapMode wrap_s, WrapMode wrap_t,
                                       const TextureView& view, const ScreenRegion& region,
                                       const GroundTruthOptions& options) {
  Fnv1a hash;
  hash.value(kEvaluatorVersion);
  hash.value(texture.width);
  hash.value(texture.height);
  hash.bytes(texture.rgba.data(), texture.rgba.size() * sizeof(float));
  hash.value(wrap_s);
  hash.value(wrap_t);
  hash.value(view.width());
  hash.value(view.height());
  for (const auto* row : {&view.map().s_row, &view.map().t_row, &view.map().w_row})
    hash.bytes(row->data(), row->size() * sizeof(double));
  hash.value(region.x0);
  hash.value(region.y0);
  hash.value(region.width);
  hash.value(region.height);
  hash.value(options.tolerance);
  hash.value(options.initial_grid);
  hash.value(options.max_grid);
  return hash.hash();
}

void write_ground_truth(const std::filesystem::path& path, const GroundTruth& truth,
                        std::uint64_t fingerprint) {
  const std::size_t pixels = static_cast<std::size_t>(truth.region.width) * truth.region.height;
  if (truth.image.rgba.size() != 4 * pixels || truth.grid.size() != pixels)
    throw std::invalid_argument("write_ground_truth: image or grid size does not match region");
  Writer out;
  out.append(kMagic, sizeof kMagic);
  out.value(kFormatVersion);
  out.value(fingerprint);
  out.value(truth.region.x0);
  out.value(truth.region.y0);
  out.value(truth.region.width);
  out.value(truth.region.height);
  const GroundTruthReport& report = truth.report;
  out.value(report.pixels);
  out.value(report.capped_pixels);
  out.value(report.worst_capped_change);
  out.value(report.worst_converged_change);
  out.value(report.largest_grid);
  out.value(report.samples);
  out.value(report.seconds);
  out.append(truth.image.rgba.data(), truth.image.rgba.size() * sizeof(float));
  out.append(truth.grid.data(), truth.grid.size() * sizeof(std::int32_t));

  std::filesystem::path temporary = path;
  temporary += ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(out.bytes().data(), static_cast<std::streamsize>(out.bytes().size()));
    file.close();
    // The rename below publishes the file: only a whole one.
    if (!file) {
      std::filesystem::remove(temporary);
      throw std::runtime_error("write_ground_truth: cannot write " + temporary.string());
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error)
    throw std::runtime_error("write_ground_truth: cannot rename to " + path.string() + ": " +
                             error.message());
}

std::optional<GroundTruth> read_ground_truth(const std::filesystem::path& path,
                                             std::uint64_t fingerprint) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  Reader in(std::vector<char>(std::istreambuf_iterator<char>(file), {}));

  char magic[sizeof kMagic];
  std::uint32_t version = 0;
  std::uint64_t stored_fingerprint = 0;
  GroundTruth truth;
  ScreenRegion& region = truth.region;
  if (!in.take(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0 ||
      !in.value(version) || version != kFormatVersion || !in.value(stored_fingerprint) ||
      stored_fingerprint != fingerprint || !in.value(region.x0) || !in.value(region.y0) ||
      !in.value(region.width) || !in.value(region.height))
    return std::nullopt;
  if (region.width < 1 || region.height < 1 || region.width > (1 << 15) ||
      region.height > (1 << 15))
    return std::nullopt;
  GroundTruthReport& report = truth.report;
  if (!in.value(report.pixels) || !in.value(report.capped_pixels) ||
      !in.value(report.worst_capped_change) || !in.value(report.worst_converged_change) ||
      !in.value(report.largest_grid) || !in.value(report.samples) || !in.value(report.seconds))
    return std::nullopt;
  const std::size_t pixels = static_cast<std::size_t>(region.width) * region.height;
  truth.image = LinearImage::filled(region.width, region.height, 0.0f);
  truth.grid.assign(pixels, 0);
  if (!in.take(truth.image.rgba.data(), truth.image.rgba.size() * sizeof(float)) ||
      !in.take(truth.grid.data(), pixels * sizeof(std::int32_t)) || !in.at_end())
    return std::nullopt;
  return truth;
}

GroundTruth cached_ground_truth(const std::filesystem::path& path, const LinearImage& texture,
                                WrapMode wrap_s, WrapMode wrap_t, const TextureView& view,
                                const ScreenRegion& region, const GroundTruthOptions& options) {
  const std::uint64_t fingerprint =
      ground_truth_fingerprint(texture, wrap_s, wrap_t, view, region, options);
  if (std::optional<GroundTruth> stored = read_ground_truth(path, fingerprint)) return *stored;
  GroundTruth truth = ground_truth(texture, wrap_s, wrap_t, view, region, options);
  write_ground_truth(path, truth, fingerprint);
  return truth;
}

std::filesystem::path default_cache_directory() {
  for (const char* variable : {"XDG_CACHE_HOME", "HOME"}) {
    const char* value = std::getenv(variable);
    if (value == nullptr || value[0] != '/') continue;  // the XDG spec ignores relative paths
    const std::filesystem::path base(value);
    return variable[0] == 'X' ? base / "edgewise" : base / ".cache" / "edgewise";
  }
  throw std::runtime_error("no cache directory: set XDG_CACHE_HOME or HOME, or give --cache DIR");
}

std::filesystem::path ground_truth_file(const std::filesystem::path& directory,
                                        const std::string& name, std::uint64_t fingerprint) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fingerprint));
  return directory / (name + "_" + hex + ".ewgt");
}

}  // namespace edgewise::texture_scene
