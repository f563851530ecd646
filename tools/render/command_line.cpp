#include "render/command_line.hpp"

#include <string>

#include "common/choice_options.hpp"
#include "common/isa_options.hpp"
#include "common/option_values.hpp"
#include "common/sampler_options.hpp"
#include "common/usage_error.hpp"
#include "common/value_options.hpp"
#include "edgewise/coverage.hpp"
#include "edgewise/interpolation.hpp"
#include "render/builtin_scenes.hpp"
#include "render/image_writer.hpp"
#include "texture_io/load_options.hpp"

namespace edgewise::render_tool {
namespace {

using tools::parse_finite_float;
using tools::UsageError;

constexpr const char* kCameraGroup =
    "Camera (default: the built-in scene's camera; for --obj, one framing the mesh's box)";
constexpr const char* kPipelineGroup = "Image and pipeline";
constexpr const char* kTextureGroup = "Texture (the options after --texture need it)";
constexpr const char* kRunningGroup = "Running";

Vec3 parse_vector(std::string_view option, std::string_view text) {
  float xyz[3];
  std::string_view rest = text;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = i < 2 ? rest.find(',') : std::string_view::npos;
    const std::optional<float> value = parse_finite_float(rest.substr(0, comma));
    if (!value || (i < 2 && comma == std::string_view::npos)) {
      throw UsageError(std::string(option) + " " + tools::quoted(text) +
                       " is not three finite numbers X,Y,Z");
    }
    xyz[i] = *value;
    if (i < 2) rest.remove_prefix(comma + 1);
  }
  return {xyz[0], xyz[1], xyz[2]};
}

tools::Option add_vector_option(tools::CommandLine& command_line, const std::string& name,
                                std::optional<Vec3>& value, const std::string& description) {
  return tools::add_parsed_option(
             command_line, name, value,
             [name](const std::string& text) { return std::optional(parse_vector(name, text)); },
             description)
      .type_name("X,Y,Z");
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
    throw UsageError("--size " + tools::quoted(text) + " is not WxH with sides 1.." +
                     std::to_string(kMaxTargetSize));
  }
  if (std::int64_t{settings.width} * settings.height > kMaxPixels) {
    throw UsageError("--size " + tools::quoted(text) + " has more than " +
                     std::to_string(kMaxPixels) + " pixels");
  }
}

// An error budget (draw.hpp): a finite number, at least 0.
float parse_budget(const std::string& option, const std::string& text) {
  const float budget = tools::finite_number(option, text);
  if (budget < 0.0f) throw UsageError(option + " must be at least 0, not " + text);
  return budget;
}

void add_camera_options(tools::CommandLine& command_line, CameraOverrides& camera) {
  add_vector_option(command_line, "--eye", camera.eye, "where the camera is").group(kCameraGroup);
  add_vector_option(command_line, "--target", camera.target, "the point it looks at")
      .group(kCameraGroup);
  add_vector_option(command_line, "--up", camera.up, "the direction that is up on screen")
      .group(kCameraGroup);
  tools::add_parsed_option(
      command_line, "--fov", camera.fov_degrees,
      [](const std::string& text) {
        const float fov = tools::finite_number("--fov", text);
        if (!(fov > 0.0f && fov < 180.0f)) {
          throw UsageError("--fov " + tools::quoted(text) + " is not in (0, 180) degrees");
        }
        return std::optional(fov);
      },
      "vertical field of view, in (0, 180)")
      .type_name("DEGREES")
      .group(kCameraGroup);
  const auto distance = [](const char* option) {
    return [option](const std::string& text) {
      return std::optional(tools::finite_number(option, text));
    };
  };
  tools::add_parsed_option(command_line, "--near", camera.near_plane, distance("--near"),
                           "clip distance along the view direction")
      .type_name("N")
      .group(kCameraGroup);
  tools::add_parsed_option(command_line, "--far", camera.far_plane, distance("--far"),
                           "clip distance along the view direction")
      .type_name("F")
      .group(kCameraGroup);
  command_line
      .add_flag("--ortho", camera.orthographic,
                "orthographic: shows at every depth what the perspective camera\n"
                "shows at the target's distance; near and far hold the scene")
      .group(kCameraGroup);
}

void add_pipeline_options(tools::CommandLine& command_line, RenderCommandLine& line) {
  RenderSettings& settings = line.settings;
  DrawOptions& draw = settings.draw;
  command_line
      .add_value(
          "--size", [&settings](const std::string& text) { parse_size(text, settings); },
          "default 1280x720")
      .type_name("WxH")
      .group(kPipelineGroup);
  tools::add_enum_option(command_line, "--method", draw.interpolation,
                         "attribute interpolation method (default plane_equations)")
      .group(kPipelineGroup);
  tools::add_enum_option(command_line, "--perspective", draw.perspective,
                         "attribute interpolation (default correct)")
      .group(kPipelineGroup);
  tools::add_enum_option(command_line, "--shading", draw.shading, "(default diffuse)")
      .group(kPipelineGroup);
  tools::add_enum_option(command_line, "--depth-test", draw.depth_test,
                         "(default less; the depth buffer is cleared to 0 for\n"
                         "greater, to 1 otherwise)")
      .group(kPipelineGroup);
  command_line
      .add_flag(
          "--no-depth-write", [&draw] { draw.depth_write = false; },
          "leave the depth buffer as it is")
      .group(kPipelineGroup);
  tools::add_named_option(command_line, "--cull", draw.cull,
                          {CullMode::none, CullMode::clockwise, CullMode::counter_clockwise},
                          cull_mode_name,
                          "winding on screen to remove (default cw: the back faces)")
      .group(kPipelineGroup);
  tools::add_parsed_option(
      command_line, "--light", draw.light_direction,
      [](const std::string& text) { return parse_vector("--light", text); },
      "direction towards the light, world space (0,0,0: ambient only)")
      .type_name("X,Y,Z")
      .group(kPipelineGroup);
  tools::add_parsed_option(
      command_line, "--error-budget", draw.error_budget,
      [](const std::string& text) { return std::optional(parse_budget("--error-budget", text)); },
      "the largest difference from the exact methods' colour, in\n"
      "linear units (1/255 = 0.00392: one 8-bit code); draw() then\n"
      "shades a triangle or a textured tile in one colour where its\n"
      "bound allows (default: exact everywhere)")
      .type_name("B")
      .group(kPipelineGroup);
  tools::add_isa_options(command_line, line.isa,
                         "default: the best ISA of this CPU (or EDGEWISE_ISA)",
                         "the scalar reference");
  command_line.option("--isa").group(kPipelineGroup);
  command_line.option("--reference").group(kPipelineGroup);
}

void add_texture_options(tools::CommandLine& command_line, RenderCommandLine& line) {
  TextureSettings& texture = line.texture;
  tools::add_parsed_option(
      command_line, "--texture", line.texture_source,
      [](const std::string& text) {
        if (text.empty()) throw UsageError("--texture needs a file name or checker");
        return std::optional(text);
      },
      "texture the mesh: an image file (read through OpenImageIO as\n"
      "edgewise-sample reads it) or the built-in checkerboard (1024x1024\n"
      "texels, 8x8 squares). The mesh's uvs address it (an OBJ file needs\n"
      "vt lines) and its vertex colours become white: the texture gives\n"
      "the colour, which shading (flat, gouraud, diffuse) still scales")
      .type_name("FILE|checker")
      .group(kTextureGroup);
  tools::add_filter_option(command_line, texture.sampler.filter,
                           "(default trilinear; ripmaps and the summed-area table are\n"
                           "built only for their filter)")
      .group(kTextureGroup);
  command_line
      .add_flag("--each-filter", texture.each_filter,
                "one run per filter in the order above (--repeat frames each) and a\n"
                "table of their times; -o FILE.png writes FILE-<filter>.png")
      .group(kTextureGroup);
  tools::add_sampler_options(command_line, texture.sampler);
  texture_io::add_texture_load_options(command_line, texture.pyramid, texture.srgb, texture.limits);
  tools::add_enum_option(command_line, "--derivatives", texture.derivatives,
                         "the sampler's screen derivatives of (s, t): differences in\n"
                         "2x2 pixel quads, as GPUs take them (default), or exact, from the\n"
                         "plane equations");
  for (const char* name : {"--wrap", "--precision", "--lod", "--lod-bias", "--max-aniso", "--taps",
                           "--pyramid", "--srgb", "--max-texture-mb", "--derivatives"}) {
    command_line.option(name).group(kTextureGroup);
  }
}

// msaaN or ssaaN (kAntiAliasingNames) as samples and a supersampling factor.
AntiAliasing anti_aliasing_of(const std::string& name) {
  AntiAliasing aa;
  aa.name = name;
  if (name.rfind("msaa", 0) == 0) aa.samples = std::stoi(name.substr(4));
  if (name.rfind("ssaa", 0) == 0) aa.supersampling = std::stoi(name.substr(4));
  aa.resolve.supersampling = aa.supersampling;
  return aa;
}

void add_anti_aliasing_options(tools::CommandLine& command_line, AntiAliasing& aa) {
  tools::add_choice_option(
      command_line, "--aa",
      std::vector<std::string>(std::begin(kAntiAliasingNames), std::end(kAntiAliasingNames)),
      [&aa](std::size_t i) {
        const ResolveOptions resolve = aa.resolve;
        aa = anti_aliasing_of(std::string(kAntiAliasingNames[i]));
        aa.resolve.filter = resolve.filter;
        aa.resolve.srgb = resolve.srgb;
      },
      "anti-aliasing: msaaN draws into a target of N samples per pixel\n"
      "(shaded once per pixel), ssaaN at N times the size per axis\n"
      "(shaded per sample); both resolved by --resolve (default none)")
      .group(kPipelineGroup);
  tools::add_enum_option(command_line, "--resolve", aa.resolve.filter,
                         "the resolve filter of --aa, in linear light: box (the pixel's\n"
                         "samples), tent (radius 1 px) or mitchell (radius 2 px)")
      .group(kPipelineGroup);
}

void add_running_options(tools::CommandLine& command_line, RenderSettings& settings) {
  tools::add_integer_option(command_line, "--repeat", settings.repeat, 1, kMaxRepeat,
                            "draw N times into the same framebuffer, report median times")
      .group(kRunningGroup);
  tools::add_parsed_option(
      command_line, "-o", settings.output,
      [](const std::string& path) {
        image_format_for(path);  // refuse an unknown extension before any work
        return std::optional(path);
      },
      "write FILE.png (RGBA8) or FILE.exr (float R, G, B, A and the\n"
      "depth buffer as channel Z)")
      .type_name("FILE")
      .group(kRunningGroup);
  command_line
      .add_flag("--compare-isas", settings.compare_isas,
                "render with the reference once and with every supported ISA\n"
                "(--repeat times); report depth mismatches and colour differences;\n"
                "exit status 1 if any depth value or count differs")
      .group(kRunningGroup);
  tools::add_parsed_option(
      command_line, "--compare-budget", settings.compare_budget,
      [](const std::string& text) { return std::optional(parse_budget("--compare-budget", text)); },
      "render --repeat frames without and --repeat with --error-budget B,\n"
      "interleaved; report both median frame times, the constant\n"
      "fragments and the largest difference between the last two images;\n"
      "exit status 1 if it exceeds floor(255 B) codes or any depth value\n"
      "or count differs; -o FILE.png writes FILE-exact.png, FILE-budget.png")
      .type_name("B")
      .group(kRunningGroup);
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

std::vector<std::string> usage_lines() {
  return {"[--obj FILE | --scene default|sphere|torus|ground] [options]"};
}

void add_options(tools::CommandLine& command_line, RenderCommandLine& line) {
  RenderSettings& settings = line.settings;
  command_line.description(
      "Renders a mesh with edgewise::draw() and prints the pipeline's counts and stage times.");
  tools::add_text_option(command_line, "--obj", settings.obj_path, "the mesh to draw, an OBJ file")
      .type_name("FILE");
  std::vector<std::string> scenes(std::begin(kBuiltinSceneNames), std::end(kBuiltinSceneNames));
  tools::add_named_option(
      command_line, "--scene", settings.scene_name, scenes,
      [](const std::string& name) { return name; }, "a built-in scene (default default)");
  add_camera_options(command_line, settings.camera);
  add_pipeline_options(command_line, line);
  add_anti_aliasing_options(command_line, settings.aa);
  add_texture_options(command_line, line);
  add_running_options(command_line, settings);
}

RenderSettings checked_settings(const tools::CommandLine& command_line, RenderCommandLine line) {
  RenderSettings settings = std::move(line.settings);
  settings.draw.isa = line.isa;
  if (settings.obj_path && command_line.count("--scene") > 0) {
    throw UsageError("give either --obj or --scene, not both");
  }
  if (settings.compare_isas && (line.isa || settings.output || line.texture.each_filter)) {
    throw UsageError("--compare-isas takes no --isa, --reference, -o or --each-filter");
  }
  if (settings.compare_budget && (settings.compare_isas || line.texture.each_filter ||
                                  settings.aa.enabled() || settings.draw.error_budget)) {
    throw UsageError(
        "--compare-budget takes no --compare-isas, --each-filter, --aa or --error-budget");
  }
  if (command_line.count("--resolve") > 0 && !settings.aa.enabled()) {
    throw UsageError("--resolve needs --aa msaaN or ssaaN");
  }
  if (line.texture.each_filter && settings.aa.enabled()) {
    throw UsageError("--each-filter renders without anti-aliasing; give no --aa");
  }
  const std::int64_t drawn_pixels = std::int64_t{settings.width} * settings.height *
                                    settings.aa.supersampling * settings.aa.supersampling *
                                    settings.aa.samples;
  if (std::int64_t{settings.width} * settings.aa.supersampling > kMaxTargetSize ||
      std::int64_t{settings.height} * settings.aa.supersampling > kMaxTargetSize ||
      drawn_pixels > kMaxPixels) {
    throw UsageError("--aa " + settings.aa.name + " at " + std::to_string(settings.width) + "x" +
                     std::to_string(settings.height) + " draws more than " +
                     std::to_string(kMaxPixels) + " samples or a side beyond " +
                     std::to_string(kMaxTargetSize));
  }
  if (!line.texture_source) {
    // The first option given that needs --texture.
    for (const tools::Option& option : command_line.given_in_order()) {
      if (option.group_name() == kTextureGroup) {
        throw UsageError(option.name() + " needs --texture FILE|checker");
      }
    }
    return settings;
  }
  if (line.texture.each_filter && command_line.count("--filter") > 0) {
    throw UsageError("--each-filter renders every filter; give no --filter");
  }
  line.texture.source = std::move(*line.texture_source);
  settings.texture = std::move(line.texture);
  return settings;
}

}  // namespace edgewise::render_tool
