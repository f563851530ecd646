#include "sample/command_line.hpp"

#include <span>
#include <string>

#include "common/choice_options.hpp"
#include "common/isa_options.hpp"
#include "common/sampler_options.hpp"
#include "texture_io/load_options.hpp"

namespace edgewise::sample_tool {
namespace {

constexpr const char* kFooter =
    "Files:\n"
    "  IMG  any image OpenImageIO reads (its first subimage, full resolution, at most 32768\n"
    "       texels a side). 8-bit images become an RGBA8 texture, others (16-bit, half, float)\n"
    "       an RGBA float texture (16-bit v reads as v / 65535). Values are used as stored: alpha\n"
    "       is not premultiplied. Channels: 1 = grey (R = G = B, A = 1), 2 = grey and alpha,\n"
    "       3 = RGB (A = 1), 4 or more = the first four as RGBA.\n"
    "  Q    queries: records of six little-endian float32 (s, t, dsdx, dtdx, dsdy, dtdy), 24\n"
    "       bytes each, without header (edgewise::TextureQuery). Read 1M queries at a time;\n"
    "       a pipe works too (--queries /dev/stdin).\n"
    "  R    results: four little-endian float32 per query (linear R, G, B, A), in query order.\n"
    "       A run that fails removes it (not a device such as /dev/stdout).\n"
    "\n"
    "Exit status: 0 done; 1 a file cannot be read or written, or its contents are invalid\n"
    "(an image OpenImageIO cannot read, a query file that is not whole records); 2 a mistake on\n"
    "the command line. Errors are one line on standard error.";

// --wrap-s or --wrap-t: one axis, over --wrap.
void add_axis_wrap_option(tools::CommandLine& command_line, const std::string& name, WrapMode& wrap,
                          const std::string& description) {
  const std::span<const WrapMode> modes = values_of<WrapMode>();
  tools::add_named_option(
      command_line, name, wrap, std::vector<WrapMode>(modes.begin(), modes.end()),
      [](WrapMode mode) { return name_of(mode); }, description);
}

}  // namespace

std::vector<std::string> usage_lines() {
  return {"--texture IMG --filter NAME --queries Q --out R [options]"};
}

void add_options(tools::CommandLine& command_line, SampleSettings& settings) {
  command_line.description(
      "Samples the texture IMG with edgewise::sample() at every query of Q and writes the\n"
      "filtered colours to R; prints the texture, the sampler and the sampling speed.");
  command_line.footer(kFooter);
  tools::add_text_option(command_line, "--texture", settings.texture_path,
                         "the texture, an image file")
      .type_name("IMG")
      .required();
  tools::add_filter_option(command_line, settings.sampler.filter,
                           "ripmaps and the summed-area table are built only for their filter")
      .required();
  tools::add_text_option(command_line, "--queries", settings.queries_path,
                         "the queries, a binary file")
      .type_name("Q")
      .required();
  tools::add_text_option(command_line, "--out", settings.output_path, "the results, a binary file")
      .type_name("R")
      .required();
  // Defined after --wrap: their values are stored over its.
  tools::add_sampler_options(command_line, settings.sampler);
  add_axis_wrap_option(command_line, "--wrap-s", settings.sampler.wrap_s,
                       "s (across), over --wrap");
  add_axis_wrap_option(command_line, "--wrap-t", settings.sampler.wrap_t, "t (down), over --wrap");
  texture_io::add_texture_load_options(command_line, settings.pyramid, settings.srgb,
                                       settings.limits);
  tools::add_isa_options(command_line, settings.isa,
                         "the kernel (default: the best ISA of this CPU, or EDGEWISE_ISA)",
                         "the scalar double-precision reference kernel");
}

}  // namespace edgewise::sample_tool
