// edgewise-render: draws an OBJ mesh or a built-in scene with edgewise::draw(), writes the image
// (PNG or EXR) and prints what the pipeline did: triangles at each stage, fragments, and the time
// of each stage. --compare-isas checks every ISA against the scalar reference on the same frame;
// --texture textures the mesh, and --each-filter renders the frame once per texture filter.
// --compare-budget B renders the frame without and with DrawOptions::error_budget B and checks
// that the two images differ by at most the codes the budget allows.
// --aa msaaN or ssaaN draws into a multisampled or a larger target and resolves it (resolve.hpp)
// before writing; the resolve is timed apart from the frame.
//
// Timing: the framebuffer and the mesh's spans are set up once; each of the --repeat frames is a
// clear (timed apart) followed by one draw() call, so the frame time is the draw call alone.
#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <new>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "common/isa_options.hpp"
#include "common/median.hpp"
#include "common/run_tool.hpp"
#include "common/usage_error.hpp"
#include "edgewise/edgewise.hpp"
#include "render/builtin_scenes.hpp"
#include "render/camera_setup.hpp"
#include "render/command_line.hpp"
#include "render/image_writer.hpp"
#include "render/render_texture.hpp"
#include "scene/obj_loader.hpp"
#include "draw/draw_stages.hpp"

namespace {

using namespace edgewise;
using namespace edgewise::render_tool;
using tools::median;
using Clock = std::chrono::steady_clock;

constexpr Vec4 kBackground{0.05f, 0.06f, 0.08f, 1.0f};

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <class Vector>
std::string vector_text(const Vector& v) {
  std::ostringstream out;
  out << '(' << v.x << ", " << v.y << ", " << v.z << ')';
  return out.str();
}

// What is drawn: the mesh, the camera it comes with (built-in scenes), and its name.
struct LoadedScene {
  scene::Mesh mesh;
  std::optional<scene::SceneCamera> camera;
  std::string description;
  // The loader's warnings, one per line, printed once the frame is known to be drawn: a file
  // that then fails gets its one line of error alone.
  std::string warnings;
};

LoadedScene load_scene(const RenderSettings& settings) {
  if (!settings.obj_path) {
    scene::Scene built = make_builtin_scene(settings.scene_name);
    return {std::move(built.mesh), built.camera, "scene " + settings.scene_name, {}};
  }
  scene::MeshResult result = scene::load_obj(*settings.obj_path);
  if (!result) throw std::runtime_error(std::string(result.error()));
  std::string warnings(result.warnings());
  scene::Mesh mesh = std::move(result).mesh();
  // Diffuse shading needs normals. The loader computes smooth ones for a file that lacks some;
  // this only keeps the tool independent of that promise.
  if (mesh.normals.empty()) scene::compute_smooth_normals(mesh);
  return {std::move(mesh), std::nullopt, "OBJ " + *settings.obj_path, std::move(warnings)};
}

// Twice the area of a triangle, from its corners in double: zero where they are collinear.
double twice_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double u[3] = {double(b.x) - a.x, double(b.y) - a.y, double(b.z) - a.z};
  const double v[3] = {double(c.x) - a.x, double(c.y) - a.y, double(c.z) - a.z};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Refuses a mesh that no camera can show anything of: every triangle of zero area (collinear
// corners, or every vertex at one point). Some such triangles among others are common in real
// meshes; draw() culls them (DrawReport::culled).
void check_drawable(const scene::Mesh& mesh, const scene::Box3& bounds,
                    const std::string& description) {
  const std::size_t triangles = scene::triangle_count(mesh);
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t* corner = &mesh.indices[3 * t];
    if (twice_area(mesh.positions[corner[0]], mesh.positions[corner[1]],
                   mesh.positions[corner[2]]) > 0.0) {
      return;
    }
  }
  const Vec3& p = bounds.min;
  const bool one_point = p.x == bounds.max.x && p.y == bounds.max.y && p.z == bounds.max.z;
  throw std::runtime_error(description + ": nothing to draw: " +
                           (one_point
                                ? "every vertex is at one point " + vector_text(p)
                                : "all " + std::to_string(triangles) +
                                      " triangles have zero area (their corners are collinear)"));
}

// The camera; a mesh it cannot frame is refused naming its file (camera_setup.hpp says which).
ResolvedCamera frame_scene(const RenderSettings& settings, const LoadedScene& loaded,
                           const scene::Box3& bounds) {
  try {
    return resolve_camera(settings.camera, loaded.camera, bounds,
                          static_cast<float>(settings.width) / static_cast<float>(settings.height));
  } catch (const tools::UsageError&) {
    throw;  // a mistake on the command line, reported as such
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(loaded.description + ": " + error.what());
  }
}

void print_warning(std::string_view text) {
  std::cout.flush();
  std::cerr << "edgewise-render: warning: " << text << '\n';
}

// Triangles draw() counted as errors must not pass silently. The mesh was checked when loaded
// (finite coordinates, indices in range), so they are out of range: the camera's transform takes
// a coordinate beyond what float32 projects (draw.hpp). A failure when, with them, no triangle
// was drawn at all; otherwise the loader's warnings, and a warning when some are.
void check_frame(const DrawReport& report, const LoadedScene& loaded) {
  const std::string count = std::to_string(report.errors) + " of " +
                            std::to_string(report.triangles) +
                            (report.triangles == 1 ? " triangle" : " triangles");
  constexpr std::string_view kReason =
      "out of range (clip-space coordinates beyond 2^64, or w below 2^-125, after the camera's "
      "transform)";
  if (report.errors != 0 && report.rasterized == 0) {
    throw std::runtime_error(loaded.description + ": no triangle could be drawn: " + count + " " +
                             (report.errors == 1 ? "is " : "are ") + std::string(kReason));
  }
  std::istringstream warnings(loaded.warnings);
  for (std::string line; std::getline(warnings, line);) {
    if (!line.empty()) print_warning(line);
  }
  if (report.errors != 0) {
    print_warning(loaded.description + ": " + count + " not drawn: " + std::string(kReason));
  }
}

// With a texture, the texels give the colour: the vertex colours are left out (opaque white).
DrawMesh draw_mesh_of(const scene::Mesh& mesh, bool textured) {
  DrawMesh draw_mesh;
  draw_mesh.positions = mesh.positions;
  draw_mesh.normals = mesh.normals;
  draw_mesh.indices = mesh.indices;
  if (textured) {
    draw_mesh.uvs = mesh.uvs;
  } else {
    draw_mesh.colors = mesh.colors;
  }
  return draw_mesh;
}

// The texture, if any, and what the report says about it.
struct TextureInUse {
  RenderTexture loaded;
  const TextureSettings& settings;
  double load_seconds = 0.0;
};

// settings.draw with the camera's transform and the texture.
DrawOptions draw_options(const RenderSettings& settings, const ResolvedCamera& camera,
                         const TextureInUse* texture) {
  DrawOptions options = settings.draw;
  options.transform = camera.transform;
  if (texture != nullptr) {
    options.texture = DrawTexture{&texture->loaded.texture, texture->settings.sampler,
                                  texture->settings.derivatives};
  }
  return options;
}

// The farthest value for the depth test, so that the first surface drawn always passes.
float clear_depth(DepthTest test) {
  return test == DepthTest::greater ? 0.0f : 1.0f;
}

// The target --aa asks for: the image's size times the supersampling factor, with its samples.
Framebuffer make_framebuffer(const RenderSettings& settings) {
  const std::int32_t width = settings.width * settings.aa.supersampling;
  const std::int32_t height = settings.height * settings.aa.supersampling;
  try {
    return Framebuffer(width, height, settings.aa.samples);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error("not enough memory for a " + std::to_string(width) + "x" +
                             std::to_string(height) + " framebuffer of " +
                             std::to_string(settings.aa.samples) + " samples per pixel");
  }
}

// --repeat frames of one ISA; the framebuffer holds the last one.
struct FrameTimes {
  DrawReport report;  // of the last frame (every frame draws the same)
  double clear = 0.0, vertex = 0.0, raster = 0.0, frame = 0.0;  // medians, seconds
  double fastest_frame = 0.0;  // on a shared machine, the least disturbed frame
};

bool same_counts(const DrawReport& a, const DrawReport& b) {
  return a.triangles == b.triangles && a.clipped == b.clipped &&
         a.clip_triangles == b.clip_triangles && a.outside == b.outside && a.culled == b.culled &&
         a.errors == b.errors && a.rasterized == b.rasterized && a.fragments == b.fragments &&
         a.fragments_passed == b.fragments_passed;
}

FrameTimes render_frames(Framebuffer& framebuffer, const DrawMesh& mesh, const DrawOptions& options,
                         int repeat) {
  std::vector<double> clear(static_cast<std::size_t>(repeat)), vertex(clear.size()),
      raster(clear.size()), frame(clear.size());
  FrameTimes times;
  for (std::size_t r = 0; r < clear.size(); ++r) {
    const auto start = Clock::now();
    framebuffer.clear(kBackground, clear_depth(options.depth_test));
    clear[r] = seconds_since(start);
    // draw(), stage by stage (kernels/draw/draw_stages.hpp: the calls draw() makes), so that the
    // vertex stage and the shading are timed apart.
    const auto draw_start = Clock::now();
    detail::DrawCall call = detail::prepare_draw(framebuffer, mesh, options);
    if (call.has_work()) {
      const auto map_start = Clock::now();
      const detail::ScreenMesh screen = detail::map_to_screen(call, mesh, options);
      vertex[r] = seconds_since(map_start);
      const auto shade_start = Clock::now();
      detail::shade_screen_mesh(call, framebuffer, screen, options);
      raster[r] = seconds_since(shade_start);
    }
    frame[r] = seconds_since(draw_start);
    const DrawReport& report = call.report;
    if (r > 0 && !same_counts(report, times.report)) {
      throw std::logic_error("draw() counted differently on two identical frames");
    }
    times.report = report;
  }
  times.clear = median(clear);
  times.vertex = median(vertex);
  times.raster = median(raster);
  times.frame = median(frame);
  times.fastest_frame = *std::min_element(frame.begin(), frame.end());
  return times;
}

// ---- Printing ---------------------------------------------------------------------------------

constexpr int kLabelWidth = 20, kValueWidth = 12;

// One aligned line: label, right-aligned value, optional note.
void print_row(std::string_view label, const std::string& value, std::string_view note = {}) {
  std::cout << "  " << std::left << std::setw(kLabelWidth) << label << std::right
            << std::setw(kValueWidth) << value;
  if (!note.empty()) std::cout << "  " << note;
  std::cout << '\n';
}

void print_count(std::string_view label, std::uint64_t value, std::string_view note = {}) {
  print_row(label, std::to_string(value), note);
}

std::string milliseconds(double seconds) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << seconds * 1e3 << " ms";
  return out.str();
}

void print_time(std::string_view label, double seconds, std::string_view note = {}) {
  print_row(label, milliseconds(seconds), note);
}

void print_setup(const LoadedScene& loaded, const RenderSettings& settings,
                 const ResolvedCamera& camera, const TextureInUse* texture, std::string_view isas) {
  const WorldCamera& view = camera.view;
  const DrawOptions& d = settings.draw;
  std::cout << "edgewise-render: " << loaded.description << ", " << settings.width << "x"
            << settings.height << ", " << isas << '\n'
            << "  camera    " << (camera.orthographic ? "orthographic" : "perspective") << ", eye "
            << vector_text(view.eye) << ", target " << vector_text(view.target) << ", up "
            << vector_text(view.up) << ", ";
  if (camera.orthographic) {
    std::cout << "half height " << camera.ortho_half_height;
  } else {
    std::cout << "fov " << view.vertical_fov_degrees;
  }
  std::cout << ", near " << view.near_plane << ", far " << view.far_plane << '\n'
            << "  pipeline  " << name_of(d.shading) << " shading, " << name_of(d.interpolation)
            << ", perspective " << name_of(d.perspective) << ", depth " << name_of(d.depth_test)
            << (d.depth_write ? " with writes" : " without writes") << ", cull "
            << cull_mode_name(d.cull) << ", light " << vector_text(d.light_direction) << '\n';
  if (texture != nullptr) {
    std::cout << "  texture   " << describe_texture(texture->loaded, texture->settings) << '\n';
  }
  if (settings.aa.enabled()) {
    std::cout << "  aa        " << settings.aa.name << ", " << name_of(settings.aa.resolve.filter)
              << " resolve in linear light; drawn at " << settings.width * settings.aa.supersampling
              << "x" << settings.height * settings.aa.supersampling << " with "
              << settings.aa.samples << (settings.aa.samples == 1 ? " sample" : " samples")
              << " per pixel\n";
  }
}

void print_counts(const DrawReport& report) {
  std::cout << "triangles\n";
  print_count("in", report.triangles);
  print_count("clipped", report.clipped,
              "into " + std::to_string(report.clip_triangles) + " triangles");
  print_count("outside", report.outside);
  print_count("culled", report.culled);
  print_count("errors", report.errors);
  print_count("rasterized", report.rasterized);
  print_count("fragments", report.fragments);
  print_count("fragments passed", report.fragments_passed);
  print_count("tiles skipped", report.statistics.tiles_skipped,
              "hidden by the per-tile depth bound");
  print_count("constant", report.statistics.fragments_constant,
              "fragments given one colour under the budget");
  print_count("one texel", report.statistics.fragments_one_texel,
              "fragments given one texel value per tile under the budget");
}

// ---- The modes: one frame, --compare-isas, --each-filter, --compare-budget ---------------------

int render(const RenderSettings& settings, const LoadedScene& loaded, const DrawMesh& mesh,
           const ResolvedCamera& camera, const TextureInUse* texture, double load_seconds,
           Clock::time_point start) {
  DrawOptions options = draw_options(settings, camera, texture);
  const Isa isa = tools::tool_isa(options.isa);
  options.isa = isa;
  print_setup(loaded, settings, camera, texture, "ISA " + std::string(name_of(isa)));

  Framebuffer framebuffer = make_framebuffer(settings);
  const FrameTimes times = render_frames(framebuffer, mesh, options, settings.repeat);
  print_counts(times.report);
  check_frame(times.report, loaded);

  // --aa: the resolved image, timed apart from the frame.
  std::vector<std::uint8_t> resolved;
  double resolve_seconds = 0.0;
  if (settings.aa.enabled()) {
    resolved.resize(static_cast<std::size_t>(settings.width) * settings.height * 4);
    const auto resolve_start = Clock::now();
    resolve(framebuffer, resolved, settings.aa.resolve);
    resolve_seconds = seconds_since(resolve_start);
  }
  double write_seconds = 0.0;
  if (settings.output) {
    const auto write_start = Clock::now();
    if (settings.aa.enabled()) {
      write_rgba_image(*settings.output, settings.width, settings.height, resolved);
    } else {
      write_image(*settings.output, framebuffer);
    }
    write_seconds = seconds_since(write_start);
  }
  std::cout << "time"
            << (settings.repeat > 1 ? " (median of " + std::to_string(settings.repeat) + " frames)"
                                    : std::string())
            << '\n';
  print_time("load scene", load_seconds);
  if (texture != nullptr) print_time("load texture", texture->load_seconds, "and its pyramids");
  print_time("clear", times.clear, "not part of the frame");
  print_time("vertex stage", times.vertex, "transform, clipping, screen mapping");
  print_time("raster + shade", times.raster, "setup, coverage, depth, shading");
  print_time("frame", times.frame,
             "the draw() call" + (settings.repeat > 1
                                      ? "; fastest frame " + milliseconds(times.fastest_frame)
                                      : std::string()));
  if (settings.aa.enabled()) {
    print_time("resolve", resolve_seconds,
               std::string(name_of(settings.aa.resolve.filter)) + " filter, not part of the frame");
  }
  if (settings.output) {
    print_time("image write", write_seconds, *settings.output);
  } else {
    print_row("image write", "-", "no -o given");
  }
  print_time("total", seconds_since(start), "everything after option parsing");
  return 0;
}

// Every sample's colour and depth, sample 0's image first.
void read_every_sample(const Framebuffer& framebuffer, std::span<std::uint8_t> rgba,
                       std::span<float> depth) {
  const std::size_t pixels = static_cast<std::size_t>(framebuffer.width()) *
                             static_cast<std::size_t>(framebuffer.height());
  for (int k = 0; k < framebuffer.samples(); ++k) {
    const std::size_t first = pixels * static_cast<std::size_t>(k);
    framebuffer.read_rgba8(rgba.subspan(4 * first, 4 * pixels), k);
    framebuffer.read_depth(depth.subspan(first, pixels), k);
  }
}

struct Difference {
  std::uint64_t depth_mismatches = 0;  // samples whose depth bits differ
  std::uint64_t colour_pixels = 0;     // samples whose colour differs
  int max_colour_codes = 0;            // largest difference of one component, in 1/255
};

Difference compare_images(std::span<const std::uint8_t> rgba, std::span<const float> depth,
                          std::span<const std::uint8_t> reference_rgba,
                          std::span<const float> reference_depth) {
  Difference d;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    d.depth_mismatches +=
        std::bit_cast<std::uint32_t>(depth[i]) != std::bit_cast<std::uint32_t>(reference_depth[i]);
    int pixel_max = 0;
    for (std::size_t c = 0; c < 4; ++c) {
      pixel_max =
          std::max(pixel_max, std::abs(int{rgba[4 * i + c]} - int{reference_rgba[4 * i + c]}));
    }
    d.colour_pixels += pixel_max > 0;
    d.max_colour_codes = std::max(d.max_colour_codes, pixel_max);
  }
  return d;
}

// A table row: the first cell left-aligned, the others right-aligned, each in its width.
template <std::size_t N>
void print_table_row(const std::array<std::string, N>& cells, const std::array<int, N>& widths) {
  std::cout << "  " << std::left << std::setw(widths[0]) << cells[0] << std::right;
  for (std::size_t c = 1; c < N; ++c)
    std::cout << std::setw(widths[c]) << cells[c];
  std::cout << '\n';
}

// A row of the --compare-isas table.
void print_isa_row(const std::array<std::string, 7>& cells) {
  print_table_row(cells, {11, 11, 11, 18, 20, 17, 8});
}

int compare_isas(const RenderSettings& settings, const LoadedScene& loaded, const DrawMesh& mesh,
                 const ResolvedCamera& camera, const TextureInUse* texture) {
  DrawOptions options = draw_options(settings, camera, texture);
  print_setup(loaded, settings, camera, texture, "every supported ISA against the reference");

  Framebuffer framebuffer = make_framebuffer(settings);
  const std::size_t values = static_cast<std::size_t>(framebuffer.width()) *
                             static_cast<std::size_t>(framebuffer.height()) *
                             static_cast<std::size_t>(framebuffer.samples());
  std::vector<std::uint8_t> reference_rgba(values * 4), rgba(values * 4);
  std::vector<float> reference_depth(values), depth(values);

  options.isa = Isa::reference;
  const FrameTimes reference = render_frames(framebuffer, mesh, options, 1);
  read_every_sample(framebuffer, reference_rgba, reference_depth);
  print_counts(reference.report);
  check_frame(reference.report, loaded);

  std::cout << "ISAs against the reference (frame: median of " << settings.repeat
            << " frames; the reference: 1 frame)\n";
  print_isa_row({"ISA", "frame", "fastest", "depth mismatches", "colour pixels diff",
                 "max colour diff", "counts"});
  print_isa_row({"reference", milliseconds(reference.frame), "-", "-", "-", "-", "-"});
  std::uint64_t depth_mismatches = 0;
  int max_colour_codes = 0;
  bool counts_match = true;
  int compared = 0;
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;
    options.isa = isa;
    const FrameTimes times = render_frames(framebuffer, mesh, options, settings.repeat);
    read_every_sample(framebuffer, rgba, depth);
    const Difference d = compare_images(rgba, depth, reference_rgba, reference_depth);
    const bool same = same_counts(times.report, reference.report);
    print_isa_row(
        {std::string(name_of(isa)), milliseconds(times.frame), milliseconds(times.fastest_frame),
         std::to_string(d.depth_mismatches), std::to_string(d.colour_pixels),
         std::to_string(d.max_colour_codes) + (d.max_colour_codes == 1 ? " code" : " codes"),
         same ? "same" : "DIFFER"});
    depth_mismatches += d.depth_mismatches;
    max_colour_codes = std::max(max_colour_codes, d.max_colour_codes);
    counts_match = counts_match && same;
    ++compared;
  }
  const bool ok = depth_mismatches == 0 && counts_match;
  std::cout << "compare-isas: " << compared << " ISAs against the reference, " << depth_mismatches
            << " depth mismatches, max colour difference " << max_colour_codes
            << (max_colour_codes == 1 ? " code" : " codes") << ", counts "
            << (counts_match ? "identical" : "DIFFERENT") << (ok ? "" : ": FAILED") << '\n';
  return ok ? 0 : 1;
}

// A row of the --each-filter table.
void print_filter_row(const std::array<std::string, 6>& cells) {
  print_table_row(cells, {20, 11, 11, 16, 12, 0});
}

// --each-filter: the frame once per texture filter (--repeat frames each), a row of times each.
int render_each_filter(const RenderSettings& settings, const LoadedScene& loaded,
                       const DrawMesh& mesh, const ResolvedCamera& camera,
                       const TextureInUse& texture) {
  DrawOptions options = draw_options(settings, camera, &texture);
  const Isa isa = tools::tool_isa(options.isa);
  options.isa = isa;
  print_setup(loaded, settings, camera, &texture, "ISA " + std::string(name_of(isa)));

  Framebuffer framebuffer = make_framebuffer(settings);
  std::cout << "each filter"
            << (settings.repeat > 1 ? " (median of " + std::to_string(settings.repeat) + " frames)"
                                    : std::string())
            << '\n';
  print_filter_row({"filter", "frame", "fastest", "raster + shade", "fragments", "  image"});
  DrawReport report;
  for (TextureFilter filter : values_of<TextureFilter>()) {
    options.texture->sampler.filter = filter;
    const FrameTimes times = render_frames(framebuffer, mesh, options, settings.repeat);
    // Appended rather than concatenated: g++ 12 warns falsely (-Wrestrict) on "-" + string.
    std::string image = "  ";
    if (settings.output) {
      std::string suffix = "-";
      suffix += name_of(filter);
      const std::string path = path_with_suffix(*settings.output, suffix);
      write_image(path, framebuffer);
      image += path;
    } else {
      image += '-';
    }
    print_filter_row({std::string(name_of(filter)), milliseconds(times.frame),
                      milliseconds(times.fastest_frame), milliseconds(times.raster),
                      std::to_string(times.report.fragments), image});
    report = times.report;
  }
  // The filter changes colours only: every frame counted the same as this last one.
  print_counts(report);
  check_frame(report, loaded);
  return 0;
}

// --repeat frames without and with the budget, interleaved (exact, budget, exact, ...) so that
// whatever else slows the machine slows both alike; the two framebuffers hold the last of each.
struct InterleavedFrames {
  std::vector<double> exact_seconds, budget_seconds;  // one per frame
  DrawReport exact_report, budget_report;             // every frame of each counts the same
};

InterleavedFrames render_interleaved(Framebuffer& exact_target, Framebuffer& budget_target,
                                     const DrawMesh& mesh, const DrawOptions& exact,
                                     const DrawOptions& budgeted, int repeat) {
  InterleavedFrames frames;
  // One untimed frame of each first: the first frame of a run also pays for the threads' start
  // and cold caches, which would fall on the exact frames alone.
  frames.exact_report = render_frames(exact_target, mesh, exact, 1).report;
  frames.budget_report = render_frames(budget_target, mesh, budgeted, 1).report;
  for (int r = 0; r < repeat; ++r) {
    const FrameTimes e = render_frames(exact_target, mesh, exact, 1);
    const FrameTimes b = render_frames(budget_target, mesh, budgeted, 1);
    if (!same_counts(e.report, frames.exact_report) ||
        !same_counts(b.report, frames.budget_report) ||
        b.report.statistics.fragments_constant !=
            frames.budget_report.statistics.fragments_constant ||
        b.report.statistics.fragments_one_texel !=
            frames.budget_report.statistics.fragments_one_texel) {
      throw std::logic_error("draw() counted differently on two identical frames");
    }
    frames.exact_seconds.push_back(e.frame);
    frames.budget_seconds.push_back(b.frame);
  }
  return frames;
}

// The codes a budget lets a colour differ by, as draw.hpp promises them: floor(255 B), at most 255.
int promised_codes(float budget) {
  const double codes = std::floor(255.0 * static_cast<double>(budget));
  return codes < 255.0 ? static_cast<int>(codes) : 255;
}

std::string codes_text(int codes) {
  return std::to_string(codes) + (codes == 1 ? " code" : " codes");
}

std::string fixed_text(double value, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

// --compare-budget: the frame without and with settings.compare_budget, their times, and the
// check: the last two images differ by at most the budget's codes in any channel of any pixel,
// their depth values and counts not at all.
int compare_budget(const RenderSettings& settings, const LoadedScene& loaded, const DrawMesh& mesh,
                   const ResolvedCamera& camera, const TextureInUse* texture) {
  DrawOptions exact = draw_options(settings, camera, texture);
  exact.isa = tools::tool_isa(exact.isa);
  DrawOptions budgeted = exact;
  budgeted.error_budget = settings.compare_budget;
  const int allowed = promised_codes(*settings.compare_budget);
  print_setup(loaded, settings, camera, texture, "ISA " + std::string(name_of(*exact.isa)));
  std::cout << "  budget    " << *settings.compare_budget << " (" << codes_text(allowed)
            << "), against the exact methods\n";

  Framebuffer exact_target = make_framebuffer(settings), budget_target = make_framebuffer(settings);
  const InterleavedFrames frames =
      render_interleaved(exact_target, budget_target, mesh, exact, budgeted, settings.repeat);
  print_counts(frames.budget_report);
  check_frame(frames.budget_report, loaded);

  const std::size_t pixels = static_cast<std::size_t>(settings.width) * settings.height;
  std::vector<std::uint8_t> exact_rgba(4 * pixels), budget_rgba(4 * pixels);
  std::vector<float> exact_depth(pixels), budget_depth(pixels);
  read_every_sample(exact_target, exact_rgba, exact_depth);
  read_every_sample(budget_target, budget_rgba, budget_depth);
  const Difference d = compare_images(budget_rgba, budget_depth, exact_rgba, exact_depth);
  const bool counts_match = same_counts(frames.budget_report, frames.exact_report);

  const double exact_median = median(frames.exact_seconds);
  const double budget_median = median(frames.budget_seconds);
  const auto fastest = [](const std::vector<double>& seconds) {
    return "fastest frame " + milliseconds(*std::min_element(seconds.begin(), seconds.end()));
  };
  const std::uint64_t written = frames.budget_report.fragments_passed;
  const std::uint64_t constant = frames.budget_report.statistics.fragments_constant;
  const double share =
      written > 0 ? 100.0 * static_cast<double>(constant) / static_cast<double>(written) : 0.0;
  std::cout << "without and with the budget (median of " << settings.repeat
            << (settings.repeat == 1 ? " frame" : " frames")
            << " each, interleaved, after one untimed pair)\n";
  print_time("exact frame", exact_median, fastest(frames.exact_seconds));
  print_time("budget frame", budget_median, fastest(frames.budget_seconds));
  print_row("ratio", fixed_text(exact_median / budget_median, 3),
            "exact / budget: above 1, the budget is faster");
  print_count("constant", constant, fixed_text(share, 1) + "% of the fragments written");
  const std::uint64_t one_texel = frames.budget_report.statistics.fragments_one_texel;
  print_count(
      "one texel", one_texel,
      fixed_text(
          written > 0 ? 100.0 * static_cast<double>(one_texel) / static_cast<double>(written) : 0.0,
          1) +
          "% of the fragments written");
  print_row("largest difference", codes_text(d.max_colour_codes),
            "any channel, any pixel, last images; the budget allows " + std::to_string(allowed));
  print_count("pixels differing", d.colour_pixels, "of " + std::to_string(pixels));
  print_count("depth mismatches", d.depth_mismatches);
  if (settings.output) {
    const std::string exact_path = path_with_suffix(*settings.output, "-exact");
    const std::string budget_path = path_with_suffix(*settings.output, "-budget");
    const auto write_start = Clock::now();
    write_image(exact_path, exact_target);
    write_image(budget_path, budget_target);
    print_time("image write", seconds_since(write_start), exact_path + ", " + budget_path);
  }

  const bool within = d.max_colour_codes <= allowed;
  const bool ok = within && d.depth_mismatches == 0 && counts_match;
  std::cout << "compare-budget: check " << (ok ? "passed" : "FAILED") << ": largest difference "
            << codes_text(d.max_colour_codes) << (within ? ", within " : ", BEYOND ") << "the "
            << allowed << " the budget allows; " << d.depth_mismatches
            << " depth mismatches; counts " << (counts_match ? "identical" : "DIFFERENT") << '\n';
  return ok ? 0 : 1;
}

int run(const RenderSettings& settings) {
  const auto start = Clock::now();
  const LoadedScene loaded = load_scene(settings);
  const double load_seconds = seconds_since(start);
  const std::optional<scene::Box3> bounds = scene::bounding_box(loaded.mesh);
  if (!bounds) {
    throw std::runtime_error(loaded.description + ": no vertex with finite coordinates");
  }
  check_drawable(loaded.mesh, *bounds, loaded.description);
  const ResolvedCamera camera = frame_scene(settings, loaded, *bounds);
  std::optional<TextureInUse> texture;
  if (settings.texture) {
    if (loaded.mesh.uvs.empty()) {
      throw std::runtime_error(loaded.description +
                               " has no texture coordinates (vt lines); --texture needs them");
    }
    const auto texture_start = Clock::now();
    texture.emplace(TextureInUse{load_render_texture(*settings.texture), *settings.texture});
    texture->load_seconds = seconds_since(texture_start);
  }
  const TextureInUse* in_use = texture ? &*texture : nullptr;
  const DrawMesh mesh = draw_mesh_of(loaded.mesh, in_use != nullptr);
  if (settings.compare_isas) return compare_isas(settings, loaded, mesh, camera, in_use);
  if (settings.compare_budget) return compare_budget(settings, loaded, mesh, camera, in_use);
  if (in_use != nullptr && in_use->settings.each_filter) {
    return render_each_filter(settings, loaded, mesh, camera, *in_use);
  }
  return render(settings, loaded, mesh, camera, in_use, load_seconds, start);
}

}  // namespace

int main(int argc, char** argv) {
  RenderCommandLine line;
  return tools::run_tool(
      argc, argv, "edgewise-render", usage_lines(), [&line](tools::CommandLine& command_line) {
        add_options(command_line, line);
        return [command_line, &line] { return run(checked_settings(command_line, line)); };
      });
}
