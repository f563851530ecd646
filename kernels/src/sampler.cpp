// sample(): option checks, the Texture flattened for the kernels, and the choice of kernel.
#include "edgewise/sampler.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel_table.hpp"
#include "texture_description.hpp"

namespace edgewise {

void sample(const Texture& texture, const SamplerOptions& options,
            std::span<const TextureQuery> queries, std::span<Vec4> out, std::optional<Isa> isa) {
  if (queries.size() != out.size()) {
    throw std::invalid_argument("sample: " + std::to_string(queries.size()) + " queries but " +
                                std::to_string(out.size()) + " results");
  }
  detail::validate_sampler(texture, options, "sample");
  const Isa chosen = resolve_isa(isa);
  if (queries.empty()) return;
  const detail::FlatTexture flat(texture);
  detail::kernel_table(chosen).sample(flat.description(), options, queries.data(), queries.size(),
                                      out.data());
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
