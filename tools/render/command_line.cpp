#include "render/command_line.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <system_error>

#include "option_values.hpp"
#include "edgewise/interpolation.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/coverage.hpp"
#include "render/builtin_scenes.hpp"
#include "render/image_writer.hpp"
#include "render/render_texture.hpp"
#include "render/usage_error.hpp"

namespace edgewise::render_tool {

const std::string_view kUsage =
    "usage: edgewise-render [--obj FILE | --scene default|sphere|torus|ground] [options]\n"
    "\n"
    "Renders a mesh with edgewise::draw() and prints the pipeline's counts and stage times.\n"
    "\n"
    "Camera (default: the built-in scene's camera; for --obj, one framing the mesh's box):\n"
    "  --eye X,Y,Z --target X,Y,Z --up X,Y,Z\n"
    "  --fov DEGREES          vertical field of view, in (0, 180)\n"
    "  --near N --far F       clip distances along the view direction\n"
    "  --ortho                orthographic: shows at every depth what the perspective camera\n"
    "                         shows at the target's distance; near and far hold the scene\n"
    "Image and pipeline:\n"
    "  --size WxH             default 1280x720\n"
    "  --method NAME          nearest_vertex, inverse_distance, subtriangle_areas,\n"
    "                         edge_functions, scanline, plane_equations (default)\n"
    "  --perspective correct|affine   attribute interpolation (default correct)\n"
    "  --shading flat|gouraud|diffuse (default diffuse)\n"
    "  --depth-test less|less_equal|greater|always|never (default less; the depth buffer is\n"
    "                         cleared to 0 for greater, to 1 otherwise)\n"
    "  --no-depth-write\n"
    "  --cull none|cw|ccw     winding on screen to remove (default cw: the back faces)\n"
    "  --light X,Y,Z          direction towards the light, world space (0,0,0: ambient only)\n"
    "  --isa NAME | --reference   default: the best ISA of this CPU (or EDGEWISE_ISA)\n"
    "Texture (the options after --texture need it):\n"
    "  --texture FILE|checker texture the mesh: an image file (read through OpenImageIO as\n"
    "                         edgewise-sample reads it) or the built-in checkerboard (1024x1024\n"
    "                         texels, 8x8 squares). The mesh's uvs address it (an OBJ file needs\n"
    "                         vt lines) and its vertex colours become white: the texture gives\n"
    "                         the colour, which shading (flat, gouraud, diffuse) still scales\n"
    "  --filter NAME          nearest, bilinear, bicubic_catmull_rom, bicubic_bspline,\n"
    "                         mip_nearest, trilinear (default), supersample, ripmap, summed_area,\n"
    "                         anisotropic, ewa (ripmaps and the summed-area table are built only\n"
    "                         for their filter)\n"
    "  --each-filter          one run per filter in the order above (--repeat frames each) and a\n"
    "                         table of their times; -o FILE.png writes FILE-<filter>.png\n"
    "  --wrap W               repeat (default), clamp or mirror, on both axes\n"
    "  --lod exact|max_axis   level-of-detail formula (default exact)\n"
    "  --lod-bias F           added to log2 of the footprint (default 0)\n"
    "  --max-aniso N          anisotropic probes, EWA eccentricity: 1..64 (default 16)\n"
    "  --taps N               supersample: N x N taps, 1..16 (default 4)\n"
    "  --pyramid box|lanczos3 how coarser levels are made (default box)\n"
    "  --srgb                 R, G, B are sRGB-encoded: 8-bit texels are decoded by the sampler,\n"
    "                         others when loaded; alpha is linear\n"
    "  --derivatives quad|analytic   the sampler's screen derivatives of (s, t): differences in\n"
    "                         2x2 pixel quads, as GPUs take them (default), or exact, from the\n"
    "                         plane equations\n"
    "Running:\n"
    "  --repeat N             draw N times into the same framebuffer, report median times\n"
    "  -o FILE                write FILE.png (RGBA8) or FILE.exr (float R, G, B, A and the\n"
    "                         depth buffer as channel Z)\n"
    "  --compare-isas         render with the reference once and with every supported ISA\n"
    "                         (--repeat times); report depth mismatches and colour differences;\n"
    "                         exit status 1 if any depth value or count differs\n";

namespace {

using tools::parse_finite_float;
using tools::quoted;
using Values = tools::OptionValues<UsageError>;

Vec3 parse_vector(std::string_view option, std::string_view text) {
  float xyz[3];
  std::string_view rest = text;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = i < 2 ? rest.find(',') : std::string_view::npos;
    const std::optional<float> value = parse_finite_float(rest.substr(0, comma));
    if (!value || (i < 2 && comma == std::string_view::npos)) {
      throw UsageError(std::string(option) + " " + quoted(text) +
                       " is not three finite numbers X,Y,Z");
    }
    xyz[i] = *value;
    if (i < 2) rest.remove_prefix(comma + 1);
  }
  return {xyz[0], xyz[1], xyz[2]};
}

std::int32_t parse_side(std::string_view text, bool& ok) {
  const std::optional<std::int64_t> value = tools::parse_integer(text);
  ok = value && *value >= 1 && *value <= kMaxTargetSize;
  return ok ? static_cast<std::int32_t>(*value) : 0;
}

void parse_size(std::string_view text, RenderSettings& settings) {
  const std::size_t x = text.find('x');
  bool width_ok = false, height_ok = false;
  if (x != std::string_view::npos) {
    settings.width = parse_side(text.substr(0, x), width_ok);
    settings.height = parse_side(text.substr(x + 1), height_ok);
  }
  if (!width_ok || !height_ok) {
    throw UsageError("--size " + quoted(text) + " is not WxH with sides 1.." +
                     std::to_string(kMaxTargetSize));
  }
  if (std::int64_t{settings.width} * settings.height > kMaxPixels) {
    throw UsageError("--size " + quoted(text) + " has more than " + std::to_string(kMaxPixels) +
                     " pixels");
  }
}

Isa parse_isa_option(std::string_view name) {
  try {
    return parse_supported_isa(name);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
}

std::optional<CullMode> parse_cull_mode(std::string_view name) {
  for (CullMode mode : {CullMode::none, CullMode::clockwise, CullMode::counter_clockwise}) {
    if (cull_mode_name(mode) == name) return mode;
  }
  return std::nullopt;
}

// "nearest, bilinear, ... or ewa", from the filters themselves.
std::string texture_filter_list() {
  std::string names;
  for (std::size_t i = 0; i < std::size(kEveryTextureFilter); ++i) {
    if (i > 0) names += i + 1 == std::size(kEveryTextureFilter) ? " or " : ", ";
    names += name_of(kEveryTextureFilter[i]);
  }
  return names;
}

// Parses the texture option `arg` into `texture`; false when `arg` is no texture option.
template <class Value>
bool parse_texture_option(std::string_view arg, Value value, TextureSettings& texture) {
  SamplerOptions& sampler = texture.sampler;
  if (arg == "--filter") {
    sampler.filter = Values::named(arg, value(), parse_name<TextureFilter>, texture_filter_list());
  } else if (arg == "--each-filter") {
    texture.each_filter = true;
  } else if (arg == "--wrap") {
    sampler.wrap_s = sampler.wrap_t =
        Values::named(arg, value(), parse_name<WrapMode>, "repeat, clamp or mirror");
  } else if (arg == "--lod") {
    sampler.lod = Values::named(arg, value(), parse_name<LodFormula>, "exact or max_axis");
  } else if (arg == "--lod-bias") {
    sampler.lod_bias = Values::number(arg, value());
  } else if (arg == "--max-aniso") {
    sampler.max_anisotropy = Values::integer_in(arg, value(), 1, kMaxAnisotropyLimit);
  } else if (arg == "--taps") {
    sampler.supersample_taps = Values::integer_in(arg, value(), 1, kMaxSupersampleTaps);
  } else if (arg == "--pyramid") {
    texture.pyramid = Values::named(arg, value(), parse_name<PyramidFilter>, "box or lanczos3");
  } else if (arg == "--srgb") {
    texture.srgb = true;
  } else if (arg == "--derivatives") {
    texture.derivatives =
        Values::named(arg, value(), parse_name<TextureDerivatives>, "quad or analytic");
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::string_view cull_mode_name(CullMode mode) {
  switch (mode) {
    case CullMode::none:
      return "none";
    case CullMode::clockwise:
      return "cw";
    case CullMode::counter_clockwise:
      return "ccw";
  }
  return "unknown";
}

RenderSettings parse_command_line(std::span<char* const> args) {
  RenderSettings settings;
  bool scene_given = false, isa_given = false;
  // Texture options may come before --texture; they are checked against it at the end.
  TextureSettings texture;
  std::optional<std::string> texture_source;
  std::string first_texture_option;
  bool filter_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    const auto value = [&]() -> std::string_view {
      if (i + 1 == args.size()) throw UsageError(std::string(arg) + " needs a value");
      return args[++i];
    };
    const auto set_isa = [&](Isa isa) {
      if (isa_given) throw UsageError("give at most one of --isa and --reference");
      isa_given = true;
      settings.draw.isa = isa;
    };
    CameraOverrides& camera = settings.camera;
    if (arg == "-h" || arg == "--help") {
      settings.help = true;
    } else if (arg == "--obj") {
      settings.obj_path = std::string(value());
    } else if (arg == "--scene") {
      const std::string_view name = value();
      if (!is_builtin_scene(name)) {
        throw UsageError("unknown --scene value " + quoted(name) + "; expected " +
                         builtin_scene_list());
      }
      settings.scene_name = std::string(name);
      scene_given = true;
    } else if (arg == "--eye") {
      camera.eye = parse_vector(arg, value());
    } else if (arg == "--target") {
      camera.target = parse_vector(arg, value());
    } else if (arg == "--up") {
      camera.up = parse_vector(arg, value());
    } else if (arg == "--fov") {
      const std::string_view text = value();
      camera.fov_degrees = Values::number(arg, text);
      if (!(*camera.fov_degrees > 0.0f && *camera.fov_degrees < 180.0f)) {
        throw UsageError("--fov " + quoted(text) + " is not in (0, 180) degrees");
      }
    } else if (arg == "--near") {
      camera.near_plane = Values::number(arg, value());
    } else if (arg == "--far") {
      camera.far_plane = Values::number(arg, value());
    } else if (arg == "--ortho") {
      camera.orthographic = true;
    } else if (arg == "--size") {
      parse_size(value(), settings);
    } else if (arg == "--method") {
      settings.draw.interpolation =
          Values::named(arg, value(), parse_name<InterpolationMethod>,
                        "nearest_vertex, inverse_distance, subtriangle_areas, edge_functions, "
                        "scanline or plane_equations");
    } else if (arg == "--perspective") {
      settings.draw.perspective =
          Values::named(arg, value(), parse_name<Perspective>, "correct or affine");
    } else if (arg == "--shading") {
      settings.draw.shading =
          Values::named(arg, value(), parse_name<Shading>, "flat, gouraud or diffuse");
    } else if (arg == "--depth-test") {
      settings.draw.depth_test = Values::named(arg, value(), parse_name<DepthTest>,
                                               "less, less_equal, greater, always or never");
    } else if (arg == "--no-depth-write") {
      settings.draw.depth_write = false;
    } else if (arg == "--cull") {
      settings.draw.cull = Values::named(arg, value(), parse_cull_mode, "none, cw or ccw");
    } else if (arg == "--light") {
      settings.draw.light_direction = parse_vector(arg, value());
    } else if (arg == "--isa") {
      set_isa(parse_isa_option(value()));
    } else if (arg == "--reference") {
      set_isa(Isa::reference);
    } else if (arg == "--texture") {
      texture_source = std::string(value());
      if (texture_source->empty()) throw UsageError("--texture needs a file name or checker");
    } else if (parse_texture_option(arg, value, texture)) {
      if (first_texture_option.empty()) first_texture_option = arg;
      filter_given = filter_given || arg == "--filter";
    } else if (arg == "--repeat") {
      settings.repeat = Values::integer_in(arg, value(), 1, kMaxRepeat);
    } else if (arg == "-o") {
      const std::string_view path = value();
      image_format_for(path);  // refuse an unknown extension before any work
      settings.output = std::string(path);
    } else if (arg == "--compare-isas") {
      settings.compare_isas = true;
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + quoted(arg));
    } else {
      throw UsageError("unexpected argument " + quoted(arg));
    }
  }
  if (settings.obj_path && scene_given) throw UsageError("give either --obj or --scene, not both");
  if (settings.compare_isas && (isa_given || settings.output || texture.each_filter)) {
    throw UsageError("--compare-isas takes no --isa, --reference, -o or --each-filter");
  }
  if (!texture_source) {
    if (!first_texture_option.empty()) {
      throw UsageError(first_texture_option + " needs --texture FILE|checker");
    }
    return settings;
  }
  if (texture.each_filter && filter_given) {
    throw UsageError("--each-filter renders every filter; give no --filter");
  }
  texture.source = std::move(*texture_source);
  settings.texture = std::move(texture);
  return settings;
}

}  // namespace edgewise::render_tool
