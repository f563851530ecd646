// Resolving a multisampled or supersampled target to its anti-aliased image
// (docs/design/anti-aliasing.md): each output pixel is the weighted mean of the samples around its
// centre, taken in linear light (the framebuffer's values are linear, framebuffer.hpp), under one
// of three reconstruction filters, and encoded as linear or sRGB 8-bit values.
//
// Sample positions: sample k of source pixel (X, Y) lies at its centre moved by the pattern's
// offset (multisample.hpp), and with supersampling factor f the source is f times the output
// per axis, so in output pixels that sample is at ((X + 0.5 + sx / 16) / f, (Y + 0.5 + sy / 16)
// / f). A filter weighs a sample by k(dx) k(dy), dx and dy its distance from the output pixel's
// centre in output pixels; the weights of each output pixel are normalized to sum to 1. Samples
// beyond the image repeat its edge pixels. R, G, B and A are filtered alike (unpremultiplied).
//
// Every ISA gives the scalar reference's image bit for bit.
//
// Thread safety: resolve() only reads the source; calls may run at once on one source.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "edgewise/framebuffer.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/names.hpp"
#include "edgewise/threads.hpp"

namespace edgewise {

enum class ResolveFilter : std::uint8_t {
  box,       // k(d) = 1 for -1/2 <= d < 1/2: the mean of the pixel's own samples (radius 1/2 px)
  tent,      // k(d) = max(0, 1 - |d|): radius 1 px
  mitchell,  // Mitchell-Netravali, B = C = 1/3: radius 2 px, with small negative lobes
};

struct ResolveOptions {
  ResolveFilter filter = ResolveFilter::box;
  // Supersampling (SSAA) by this factor per axis: the source was drawn at factor times the
  // output's width and height, and the output is source.width() / factor by
  // source.height() / factor. 1 resolves a multisampled target at its own size.
  int supersampling = 1;
  // The output's R, G and B encoded as sRGB (IEC 61966-2-1), else linear like the framebuffer;
  // alpha stays linear.
  bool srgb = false;
  std::optional<Isa> isa;  // default: active_isa()
  // Threads (threads.hpp): 0 takes default_thread_count(), 1 resolves on the calling thread
  // alone; bands of output rows run apart, and the image is the same bit for bit for every count.
  std::size_t threads = 0;
  // Runs the call's tasks on those threads; empty: oneTBB's (threads.hpp states the contract).
  TaskExecutor executor;
};

// Writes the resolved image, row-major, 4 bytes (R, G, B, A) per pixel, each value the filtered
// one clamped to [0, 1] and rounded to nearest. Throws std::invalid_argument for a
// supersampling factor below 1 or one that divides neither side exactly, a span that is not
// (width / factor) * (height / factor) * 4 bytes, an ISA this CPU lacks, or more threads than
// kMaxThreads.
void resolve(const Framebuffer& source, std::span<std::uint8_t> rgba,
             const ResolveOptions& options = {});

// The filter's reach from the output pixel's centre, in output pixels (1/2, 1 or 2).
double filter_radius(ResolveFilter filter);

// The filter's one-dimensional kernel k(d), d in output pixels.
double filter_weight(ResolveFilter filter, double d);

std::string_view name_of(ResolveFilter value);
template <>
std::span<const ResolveFilter> values_of<ResolveFilter>();

}  // namespace edgewise
