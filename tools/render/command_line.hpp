// edgewise-render's command line: every option parsed and range-checked up front, so that
// a typo costs no loading or rendering. Mistakes throw UsageError (common/usage_error.hpp) naming
// the option and the value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/command_line.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/resolve.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "edgewise/vector.hpp"
#include "texture_io/texture_loader.hpp"

namespace edgewise::render_tool {

// Camera values given on the command line; the others come from the scene (camera_setup.hpp).
struct CameraOverrides {
  std::optional<Vec3> eye, target, up;
  std::optional<float> fov_degrees;  // in (0, 180)
  std::optional<float> near_plane, far_plane;
  bool orthographic = false;
};

// Back faces are culled by default. Meshes wind their front faces counter-clockwise as seen
// from the front (testing/scene/mesh.hpp); the projection keeps what the eye sees, so on screen
// they still look counter-clockwise. The viewport's y flip only changes the sign of the winding
// formula, which coverage.hpp's CullMode already defines in y-down screen coordinates: front faces
// are CullMode::counter_clockwise there, and the back faces, to remove, clockwise.
inline constexpr CullMode kBackFaceCull = CullMode::clockwise;

// Towards the light in world space (where the meshes' normals are): above, left of and in front
// of the built-in scenes' cameras.
inline constexpr Vec3 kDefaultLight{-0.45f, 0.8f, 0.55f};

// --texture's value that names the built-in checkerboard rather than a file (a file of that name
// is given as ./checker).
inline constexpr std::string_view kCheckerTexture = "checker";

// --texture and the options that only mean something with it.
struct TextureSettings {
  std::string source;      // an image file, or kCheckerTexture
  SamplerOptions sampler;  // --filter (default trilinear), --wrap, --lod, --lod-bias, ...
  TextureDerivatives derivatives = TextureDerivatives::quad;  // --derivatives
  PyramidFilter pyramid = PyramidFilter::box;                 // --pyramid
  bool srgb = false;                                          // --srgb
  bool each_filter = false;       // --each-filter: one frame per TextureFilter
  texture_io::LoadLimits limits;  // --max-texture-mb
};

// --aa and --resolve: how many samples each pixel takes and how they are filtered (resolve.hpp).
struct AntiAliasing {
  std::string name = "none";  // as --aa spells it
  int samples = 1;            // msaaN: a multisampled target of N samples per pixel
  int supersampling = 1;      // ssaaN: drawn at N times the size per axis
  ResolveOptions resolve;     // --resolve; supersampling is filled in from ssaaN
  bool enabled() const { return samples > 1 || supersampling > 1; }
};

// --aa's values, in the order --help lists them.
inline constexpr std::string_view kAntiAliasingNames[] = {"none",   "msaa2", "msaa4", "msaa8",
                                                          "msaa16", "ssaa2", "ssaa3", "ssaa4"};

struct RenderSettings {
  std::optional<std::string> obj_path;  // --obj; otherwise the built-in scene below
  std::string scene_name = "default";   // --scene
  CameraOverrides camera;
  std::int32_t width = 1280, height = 720;
  std::optional<TextureSettings> texture;  // --texture
  AntiAliasing aa;                         // --aa, --resolve
  // Everything but the transform, which the camera gives, and the texture, loaded after parsing.
  DrawOptions draw = [] {
    DrawOptions options;
    options.shading = Shading::diffuse;
    options.cull = kBackFaceCull;
    options.light_direction = kDefaultLight;
    return options;
  }();
  int repeat = 1;
  std::optional<std::string> output;  // -o
  bool compare_isas = false;
  std::optional<float> compare_budget;  // --compare-budget B
};

inline constexpr int kMaxRepeat = 10000;
// A framebuffer takes 8 bytes per pixel, and writing it out up to 20 more: beyond 2^28 pixels
// (16384 x 16384) the tool refuses, rather than let the system's out-of-memory killer decide.
inline constexpr std::int64_t kMaxPixels = std::int64_t{1} << 28;

// What the options fill in as the command line is parsed; checked_settings() makes the settings of
// it.
struct RenderCommandLine {
  RenderSettings settings;
  std::optional<Isa> isa;                     // --isa or --reference
  std::optional<std::string> texture_source;  // --texture
  TextureSettings texture;                    // the options after --texture, given or not
};

// The usage lines after the tool's name, for --help.
std::vector<std::string> usage_lines();
// Adds edgewise-render's options to `command_line`; they fill `line` when it parses.
void add_options(tools::CommandLine& command_line, RenderCommandLine& line);
// The settings, once `command_line` has parsed the command line into `line`. Throws UsageError for
// options that do not go together.
RenderSettings checked_settings(const tools::CommandLine& command_line, RenderCommandLine line);

std::string_view cull_mode_name(CullMode mode);

}  // namespace edgewise::render_tool
