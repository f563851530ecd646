// Texture sampling throughput, samples per second, for every filter on every supported ISA and
// the reference, on two query streams of a 1024 x 1024 RGBA8 checkerboard (64 x 64 squares):
// - ground_plane: one query per pixel of the 1920 x 1080 ground-plane view (texture_scene),
//   footprints from magnified texels at the bottom to 30:1 anisotropic ones at the top;
// - magnification: one query per pixel of the 1920 x 1080 magnification view (six texels
//   across the screen).
// Peer: OpenImageIO's TextureSystem on the same queries and the same texture (a tiled, mipmapped
// file written at start-up), single point lookups through a texture handle.
//
// Sample/<isa>/<filter>/<stream> and SamplePeer/oiio/<mode>/<stream>; for the filters made of
// bilinear taps, Sample/<isa>/<filter>/<stream>/<precision> too: the FilterPrecision the default
// does not use (other_precision()). One iteration samples the whole stream (the reference: its
// first 1/64); items are queries. Error beside speed: the
// counters rmse and psnr_db against ground truth, when edgewise-texture-quality has stored it
// (bench_texture.hpp).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "bench_texture.hpp"
#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "texture_scene/builtin_views.hpp"
#include "texture_scene/linear_image.hpp"
#include "texture_scene/procedural_textures.hpp"

#if defined(EDGEWISE_BENCH_OIIO)
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/texture.h>
#endif

namespace edgewise::bench {
namespace {

constexpr std::size_t kReferenceQueryShare = 64;

enum class Stream { ground_plane, magnification };

const char* stream_name(Stream stream) {
  return stream == Stream::ground_plane ? "ground_plane" : "magnification";
}

const texture_scene::TextureView& view(Stream stream) {
  static const texture_scene::TextureView ground =
      texture_scene::ground_plane_view(kWidth, kHeight);
  static const texture_scene::TextureView magnified =
      texture_scene::magnification_view(kWidth, kHeight, kTextureSize, kTextureSize);
  return stream == Stream::ground_plane ? ground : magnified;
}

const std::vector<TextureQuery>& queries(Stream stream) {
  static const std::vector<TextureQuery> ground = view(Stream::ground_plane).queries();
  static const std::vector<TextureQuery> magnified = view(Stream::magnification).queries();
  return stream == Stream::ground_plane ? ground : magnified;
}

void sample_stream(benchmark::State& state, Isa isa, TextureFilter filter, Stream stream,
                   FilterPrecision precision) {
  const Texture& t = checkerboard_texture();
  std::span<const TextureQuery> q = queries(stream);
  if (isa == Isa::reference) q = q.first(q.size() / kReferenceQueryShare);
  std::vector<Vec4> out(q.size());
  SampleOptions options{SamplerOptions{}, isa};
  options.sampler.filter = filter;
  options.sampler.precision = precision;
  for (auto _ : state) {
    sample(t, options, q, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(q.size()));
  state.counters["samples"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(q.size()),
                         benchmark::Counter::kIsRate);
  if (isa != Isa::reference) report_error(state, stream_name(stream), view(stream), out);
}

#if defined(EDGEWISE_BENCH_OIIO)
struct PeerMode {
  const char* name;
  OIIO::TextureOpt::MipMode mip;
  OIIO::TextureOpt::InterpMode interpolation;
  int anisotropy;
};
constexpr PeerMode kPeerModes[] = {
    {"closest", OIIO::TextureOpt::MipModeNoMIP, OIIO::TextureOpt::InterpClosest, 1},
    {"bilinear", OIIO::TextureOpt::MipModeNoMIP, OIIO::TextureOpt::InterpBilinear, 1},
    {"bicubic", OIIO::TextureOpt::MipModeNoMIP, OIIO::TextureOpt::InterpBicubic, 1},
    {"trilinear", OIIO::TextureOpt::MipModeTrilinear, OIIO::TextureOpt::InterpBilinear, 1},
    {"anisotropic16", OIIO::TextureOpt::MipModeAniso, OIIO::TextureOpt::InterpBilinear, 16},
};

// The checkerboard as a tiled, mipmapped file that OpenImageIO's TextureSystem reads, written
// once per run (its box-filtered mipmaps match the box pyramid above).
const std::string& peer_texture_file() {
  static const std::string path = [] {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "edgewise-bench-checkerboard.tx";
    const std::vector<std::uint8_t> texels = texture_scene::to_rgba8(checkerboard());
    OIIO::ImageSpec spec(kTextureSize, kTextureSize, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf image(spec, const_cast<std::uint8_t*>(texels.data()));
    OIIO::ImageSpec config;
    config.attribute("maketx:filtername", "box");
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, image, file.string(),
                                          config)) {
      return std::string();
    }
    return file.string();
  }();
  return path;
}

void peer_stream(benchmark::State& state, PeerMode mode, Stream stream) {
  const std::string& file = peer_texture_file();
  if (file.empty()) {
    state.SkipWithError("OpenImageIO could not write the texture file");
    return;
  }
  OIIO::TextureSystem* system = OIIO::TextureSystem::create(false);
  OIIO::TextureSystem::Perthread* thread = system->get_perthread_info();
  OIIO::TextureSystem::TextureHandle* handle = system->get_texture_handle(OIIO::ustring(file));
  OIIO::TextureOpt options;
  options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
  options.mipmode = mode.mip;
  options.interpmode = mode.interpolation;
  options.anisotropic = mode.anisotropy;
  const std::vector<TextureQuery>& q = queries(stream);
  std::vector<float> out(4 * q.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < q.size(); ++i) {
      system->texture(handle, thread, options, q[i].s, q[i].t, q[i].dsdx, q[i].dtdx, q[i].dsdy,
                      q[i].dtdy, 4, &out[4 * i]);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(q.size()));
  std::vector<Vec4> colours(q.size());
  for (std::size_t i = 0; i < q.size(); ++i)
    colours[i] = {out[4 * i], out[4 * i + 1], out[4 * i + 2], out[4 * i + 3]};
  report_error(state, stream_name(stream), view(stream), colours);
  OIIO::TextureSystem::destroy(system);
}
#endif

}  // namespace

void register_sample_benchmarks() {
  for (Stream stream : {Stream::ground_plane, Stream::magnification}) {
    for (Isa isa : supported_isas()) {
      for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
        const auto filter = static_cast<TextureFilter>(f);
        const std::string name = "Sample/" + std::string(name_of(isa)) + "/" +
                                 std::string(name_of(filter)) + "/" + stream_name(stream);
        benchmark::RegisterBenchmark(name.c_str(), sample_stream, isa, filter, stream,
                                     FilterPrecision::automatic)
            ->Unit(benchmark::kMillisecond);
        // The other precision of the taps beside the default, named by a suffix.
        if (isa == Isa::reference || !reads_bilinear_taps(filter)) continue;
        const FilterPrecision other = other_precision(filter);
        benchmark::RegisterBenchmark((name + "/" + std::string(name_of(other))).c_str(),
                                     sample_stream, isa, filter, stream, other)
            ->Unit(benchmark::kMillisecond);
      }
    }
#if defined(EDGEWISE_BENCH_OIIO)
    for (const PeerMode& mode : kPeerModes) {
      const std::string name =
          "SamplePeer/oiio/" + std::string(mode.name) + "/" + stream_name(stream);
      benchmark::RegisterBenchmark(name.c_str(), peer_stream, mode, stream)
          ->Unit(benchmark::kMillisecond);
    }
#endif
  }
}

}  // namespace edgewise::bench
