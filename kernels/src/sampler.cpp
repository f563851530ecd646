// sample(): option checks, the Texture flattened for the kernels, and the choice of kernel.
#include "edgewise/sampler.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/sample_reference.hpp"
#include "sample_kernels.hpp"

namespace edgewise {
namespace {

void validate(const Texture& texture, const SamplerOptions& options) {
  if (options.max_anisotropy < 1 || options.max_anisotropy > kMaxAnisotropyLimit) {
    throw std::invalid_argument("sample: max_anisotropy " + std::to_string(options.max_anisotropy) +
                                " is outside 1 .. " + std::to_string(kMaxAnisotropyLimit));
  }
  if (options.supersample_taps < 1 || options.supersample_taps > kMaxSupersampleTaps) {
    throw std::invalid_argument("sample: supersample_taps " +
                                std::to_string(options.supersample_taps) + " is outside 1 .. " +
                                std::to_string(kMaxSupersampleTaps));
  }
  if (!std::isfinite(options.lod_bias))
    throw std::invalid_argument("sample: lod_bias is not finite");
  if (options.filter == TextureFilter::ripmap && texture.ripmap_levels().empty()) {
    throw std::invalid_argument("sample: the ripmap filter needs a texture built with ripmaps");
  }
  if (options.filter == TextureFilter::summed_area && texture.summed_area_table() == nullptr) {
    throw std::invalid_argument(
        "sample: the summed_area filter needs a texture built with a summed-area table");
  }
}

// Level sizes and starts (in texels) as the kernels read them.
struct LevelArrays {
  std::vector<std::int32_t> width, height, start;

  LevelArrays(std::span<const TextureLevel> levels, std::size_t texel_bytes) {
    for (const TextureLevel& level : levels) {
      width.push_back(level.width);
      height.push_back(level.height);
      start.push_back(static_cast<std::int32_t>(level.offset / texel_bytes));
    }
  }
  detail::LevelTable table() const {
    return {width.data(), height.data(), start.data(), static_cast<std::int32_t>(width.size())};
  }
};

detail::SampleKernel kernel_for(Isa isa) {
  switch (isa) {
#if defined(__x86_64__) || defined(_M_X64)
    case Isa::sse2:
      return &isa_sse2::sample;
    case Isa::sse4_1:
      return &isa_sse4_1::sample;
    case Isa::avx2:
      return &isa_avx2::sample;
#endif
#if defined(__aarch64__)
    case Isa::neon:
      return &isa_neon::sample;
#endif
    default:
      return nullptr;
  }
}

// The EWA weights as the kernels read them (sampler.hpp; the reference builds the same table in
// double): exp(-2 r2) - exp(-2) at r2 = i / 127, rounded once to float, and a trailing 0.
const float* ewa_weights() {
  static const auto table = [] {
    std::array<float, detail::kEwaWeights> weights{};
    for (int i = 0; i + 1 < detail::kEwaWeights; ++i) {
      const double r2 = static_cast<double>(i) / (detail::kEwaWeights - 2);
      weights[static_cast<std::size_t>(i)] =
          static_cast<float>(std::exp(-2.0 * r2) - std::exp(-2.0));
    }
    return weights;
  }();
  return table.data();
}

}  // namespace

void sample(const Texture& texture, const SamplerOptions& options,
            std::span<const TextureQuery> queries, std::span<Vec4> out, std::optional<Isa> isa) {
  if (queries.size() != out.size()) {
    throw std::invalid_argument("sample: " + std::to_string(queries.size()) + " queries but " +
                                std::to_string(out.size()) + " results");
  }
  validate(texture, options);
  const Isa chosen = isa ? *isa : active_isa();
  if (!isa_supported(chosen)) {
    throw std::invalid_argument("sample: ISA " + std::string(isa_name(chosen)) +
                                " is not supported here");
  }
  if (queries.empty()) return;
  const detail::SampleKernel kernel = kernel_for(chosen);
  if (kernel == nullptr) {
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const reference::Rgba rgba = reference::sample(texture, options, queries[i]);
      out[i] = {static_cast<float>(rgba[0]), static_cast<float>(rgba[1]),
                static_cast<float>(rgba[2]), static_cast<float>(rgba[3])};
    }
    return;
  }
  const std::size_t texel_bytes = texture.format() == TexelFormat::rgba8 ? 4 : 16;
  const LevelArrays mips(texture.mip_levels(), texel_bytes);
  const LevelArrays rips(texture.ripmap_levels(), texel_bytes);
  detail::TextureDescription description;
  description.texels = texture.storage();
  description.format = texture.format();
  description.srgb_table =
      texture.format() == TexelFormat::rgba8 && texture.encoding() == ColorEncoding::srgb
          ? srgb_decode_table().data()
          : nullptr;
  if (texture.format() == TexelFormat::rgba8) {
    for (int k = 0; k < 4; ++k) {
      description.channel_scale[k] =
          k < 3 && description.srgb_table != nullptr ? 1.0f : 1.0f / 255.0f;
    }
  }
  description.ewa_weights = ewa_weights();
  description.width = static_cast<float>(texture.width());
  description.height = static_cast<float>(texture.height());
  description.mips = mips.table();
  description.rips = rips.table();
  description.summed_area_table = texture.summed_area_table();
  description.rip_columns = texture.ripmap_columns();
  description.rip_rows =
      texture.ripmap_columns() > 0
          ? static_cast<std::int32_t>(texture.ripmap_levels().size()) / texture.ripmap_columns()
          : 0;
  kernel(description, options, queries.data(), queries.size(), out.data());
}

std::string_view texture_filter_name(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::nearest:
      return "nearest";
    case TextureFilter::bilinear:
      return "bilinear";
    case TextureFilter::bicubic_catmull_rom:
      return "bicubic_catmull_rom";
    case TextureFilter::bicubic_bspline:
      return "bicubic_bspline";
    case TextureFilter::mip_nearest:
      return "mip_nearest";
    case TextureFilter::trilinear:
      return "trilinear";
    case TextureFilter::supersample:
      return "supersample";
    case TextureFilter::ripmap:
      return "ripmap";
    case TextureFilter::summed_area:
      return "summed_area";
    case TextureFilter::anisotropic:
      return "anisotropic";
    case TextureFilter::ewa:
      return "ewa";
  }
  return "unknown";
}

std::optional<TextureFilter> parse_texture_filter(std::string_view name) {
  for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
    const auto filter = static_cast<TextureFilter>(f);
    if (texture_filter_name(filter) == name) return filter;
  }
  return std::nullopt;
}

std::string_view wrap_mode_name(WrapMode wrap) {
  switch (wrap) {
    case WrapMode::repeat:
      return "repeat";
    case WrapMode::clamp_to_edge:
      return "clamp";
    case WrapMode::mirror:
      return "mirror";
  }
  return "unknown";
}

std::optional<WrapMode> parse_wrap_mode(std::string_view name) {
  for (WrapMode wrap : {WrapMode::repeat, WrapMode::clamp_to_edge, WrapMode::mirror}) {
    if (wrap_mode_name(wrap) == name) return wrap;
  }
  return std::nullopt;
}

std::string_view lod_formula_name(LodFormula formula) {
  return formula == LodFormula::exact ? "exact" : "max_axis";
}

std::optional<LodFormula> parse_lod_formula(std::string_view name) {
  for (LodFormula formula : {LodFormula::exact, LodFormula::max_axis}) {
    if (lod_formula_name(formula) == name) return formula;
  }
  return std::nullopt;
}

}  // namespace edgewise
