// edgewise-sample: samples a texture file at the queries of a binary file with edgewise::sample()
// and writes the filtered colours, so that anyone can score the filters against their own ground
// truth (or another sampler). Prints the texture, the sampler and the sampling speed.
//
// Timing: "sampling" is the time spent inside sample() alone, summed over the chunks; reading,
// writing and building the texture are timed apart.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <span>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "common/isa_options.hpp"
#include "common/output_file.hpp"
#include "common/run_tool.hpp"
#include "common/usage_error.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "sample/command_line.hpp"
#include "sample/record_files.hpp"
#include "texture_io/texture_loader.hpp"

namespace {

using namespace edgewise;
using namespace edgewise::sample_tool;
using namespace edgewise::texture_io;
using Clock = std::chrono::steady_clock;

// Queries per call of sample(): 24 MiB of queries and 16 MiB of results in memory at a time,
// large enough that the per-call setup is negligible.
constexpr std::size_t kChunkQueries = std::size_t{1} << 20;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Writing the results over an input would destroy it before it is read.
void refuse_output_over_inputs(const SampleSettings& settings) {
  for (const std::string* input : {&settings.queries_path, &settings.texture_path}) {
    std::error_code ignored;  // a path that does not exist names no input
    if (std::filesystem::equivalent(settings.output_path, *input, ignored)) {
      throw tools::UsageError("--out " + settings.output_path + " is the input file " + *input);
    }
  }
}

TextureBuild build_for(const SampleSettings& settings) {
  TextureBuild build;
  build.filter = settings.pyramid;
  build.ripmaps = settings.sampler.filter == TextureFilter::ripmap;
  build.summed_area_table = settings.sampler.filter == TextureFilter::summed_area;
  return build;
}

std::string texture_description(const SampleSettings& settings, const LoadedTexture& loaded) {
  const Texture& texture = loaded.texture;
  std::ostringstream out;
  out << settings.texture_path << ": " << texture.width() << "x" << texture.height() << ", "
      << loaded.file_channels << (loaded.file_channels == 1 ? " channel " : " channels ")
      << loaded.pixel_type << " -> "
      << (texture.format() == TexelFormat::rgba8 ? "rgba8" : "rgba32f")
      << (settings.srgb ? " sRGB" : " linear") << ", " << texture.mip_levels().size()
      << " mip levels (" << name_of(settings.pyramid) << ")";
  if (!texture.ripmap_levels().empty()) {
    out << ", ripmaps " << texture.ripmap_columns() << "x"
        << texture.ripmap_levels().size() / static_cast<std::size_t>(texture.ripmap_columns());
  }
  if (texture.summed_area_table() != nullptr) out << ", summed-area table";
  return out.str();
}

std::string sampler_description(const SamplerOptions& options, Isa isa) {
  std::ostringstream out;
  out << name_of(options.filter) << ", wrap " << name_of(options.wrap_s) << "/"
      << name_of(options.wrap_t) << ", lod " << name_of(options.lod) << ", bias "
      << options.lod_bias << ", max aniso " << options.max_anisotropy << ", taps "
      << options.supersample_taps << ", ISA " << name_of(isa);
  return out.str();
}

std::string seconds_text(double seconds) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << seconds << " s";
  return out.str();
}

int run(const SampleSettings& settings) {
  const Isa isa = tools::tool_isa(settings.isa);
  const auto start = Clock::now();

  // Files first: a wrong path costs no texture build.
  QueryReader queries(settings.queries_path);
  refuse_output_over_inputs(settings);
  // The results, raw little-endian float32 RGBA (kResultRecordBytes each): a file that fails is
  // removed rather than left truncated (common/output_file.hpp).
  tools::OutputFile results(settings.output_path);

  const auto load_start = Clock::now();
  const LoadedTexture loaded =
      load_texture(settings.texture_path, settings.srgb, build_for(settings), settings.limits);
  const double load_seconds = seconds_since(load_start);

  const std::size_t chunk_size = static_cast<std::size_t>(
      std::min<std::uint64_t>(kChunkQueries, queries.count().value_or(kChunkQueries)));
  std::vector<TextureQuery> chunk(chunk_size);
  std::vector<Vec4> colours(chunk_size);
  std::uint64_t total = 0;
  double sampling_seconds = 0.0;
  for (std::size_t n; (n = queries.read(chunk)) > 0;) {
    const auto sample_start = Clock::now();
    sample(loaded.texture, {settings.sampler, isa}, std::span(chunk).first(n),
           std::span(colours).first(n));
    sampling_seconds += seconds_since(sample_start);
    results.write(std::as_bytes(std::span(colours).first(n)));
    total += n;
  }
  results.finish();

  std::ostringstream speed;
  if (sampling_seconds > 0.0) {
    speed << " (" << std::fixed << std::setprecision(2)
          << static_cast<double>(total) / sampling_seconds * 1e-6 << " M samples/s)";
  }
  std::cout << "edgewise-sample: " << total << " queries from " << settings.queries_path
            << ", results in " << settings.output_path << '\n'
            << "  texture   " << texture_description(settings, loaded) << '\n'
            << "  sampler   " << sampler_description(settings.sampler, isa) << '\n'
            << "  time      load texture " << seconds_text(load_seconds) << ", sampling "
            << seconds_text(sampling_seconds) << speed.str() << ", total "
            << seconds_text(seconds_since(start)) << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  SampleSettings settings;
  return tools::run_tool(argc, argv, "edgewise-sample", usage_lines(),
                         [&settings](tools::CommandLine& command_line) {
                           add_options(command_line, settings);
                           return [&settings] { return run(settings); };
                         });
}
