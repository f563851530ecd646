// edgewise-city: the procedural city of scene/city.hpp drawn whole and with occlusion culling
// (occlusion.hpp), frames of each interleaved: the median frame time of each, their ratio, what
// the culled frame spent on occluders, queries and drawing, the share of objects culled, and a
// check that the two images are identical. Exits 1 when they are not.
#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/choice_options.hpp"
#include "common/image_file.hpp"
#include "common/isa_options.hpp"
#include "common/median.hpp"
#include "common/run_tool.hpp"
#include "common/value_options.hpp"
#include "edgewise/edgewise.hpp"
#include "scene/city.hpp"
#include "scene/city_frame.hpp"

namespace {

using namespace edgewise;

struct Arguments {
  int width = 1280, height = 720;
  int frames = 7;
  int blocks = 20;
  int props = 22;
  int reduction = 1;  // of the occlusion buffer
  std::optional<Isa> isa;
  std::optional<std::string> output;
};

std::vector<std::uint8_t> pixels_of(const Framebuffer& target) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(target.width()) * target.height() * 4);
  target.read_rgba8(rgba);
  return rgba;
}

std::string ms(double seconds) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << seconds * 1e3 << " ms";
  return text.str();
}

int run(const Arguments& arguments) {
  scene::CityOptions city_options;
  city_options.blocks_per_side = arguments.blocks;
  city_options.props_per_block = arguments.props;
  const scene::City city = scene::make_city(city_options);
  const Mat4 view = scene::city_view(city, static_cast<float>(arguments.width) / arguments.height);
  scene::CityFrameOptions options;
  options.isa = arguments.isa;
  Framebuffer whole(arguments.width, arguments.height), culled(arguments.width, arguments.height);
  OcclusionBuffer occlusion(arguments.width, arguments.height, arguments.reduction);
  scene::Mesh visible;
  std::vector<double> whole_times, culled_times, occluder_times, query_times, draw_times;
  scene::CityFrame last;
  for (int f = 0; f < arguments.frames; ++f) {
    whole_times.push_back(scene::draw_city(whole, city, view, options).seconds());
    last = scene::draw_city_culled(culled, occlusion, city, view, options, visible);
    culled_times.push_back(last.seconds());
    occluder_times.push_back(last.occluder_seconds);
    query_times.push_back(last.query_seconds);
    draw_times.push_back(last.draw_seconds);
  }
  const bool identical = pixels_of(whole) == pixels_of(culled);
  const double whole_ms = tools::median(whole_times), culled_ms = tools::median(culled_times);
  const std::size_t objects = city.objects.size();
  const std::size_t props = objects - city.first_prop();
  const std::size_t culled_props = objects - last.objects_drawn;
  std::cout << "edgewise-city: " << objects << " objects (" << city.buildings
            << " buildings and the ground, the occluders; " << props << " trees), "
            << city.mesh.indices.size() / 3 << " triangles, " << arguments.width << "x"
            << arguments.height << ", ISA " << name_of(resolve_isa(arguments.isa))
            << (arguments.reduction == 1
                    ? ""
                    : ", occlusion at 1/" + std::to_string(arguments.reduction) + " resolution")
            << ", median of " << arguments.frames << " frames each\n"
            << "  whole frame     " << ms(whole_ms) << "\n"
            << "  culled frame    " << ms(culled_ms) << "  (" << std::fixed << std::setprecision(2)
            << whole_ms / culled_ms << "x faster)\n"
            << "    occluders     " << ms(tools::median(occluder_times)) << "  ("
            << city.occluder_index_count / 3 << " triangles drawn, their depth copied)\n"
            << "    queries       " << ms(tools::median(query_times)) << "  ("
            << objects - city.first_prop() << " boxes)\n"
            << "    draw          " << ms(tools::median(draw_times)) << "  ("
            << last.objects_drawn - city.first_prop() << " trees)\n"
            << "  culled          " << culled_props << " of " << props << " trees ("
            << std::setprecision(1) << 100.0 * static_cast<double>(culled_props) / props << "%), "
            << 100.0 * static_cast<double>(objects - last.objects_drawn) / objects
            << "% of all objects\n"
            << "  images          " << (identical ? "identical" : "DIFFERENT") << "\n";
  if (arguments.output) {
    tools::ImagePixels image;
    image.width = arguments.width;
    image.height = arguments.height;
    image.channels = 4;
    const std::vector<std::uint8_t> rgba = pixels_of(culled);
    image.bytes = rgba;
    tools::write_image_file(*arguments.output, image);
    std::cout << "  image           " << *arguments.output << '\n';
  }
  if (!identical) {
    std::cerr << "edgewise-city: the culled frame differs from the whole one\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments arguments;
  return tools::run_tool(
      argc, argv, "edgewise-city",
      {"[--width W] [--height H] [--frames N] [--blocks N] [--props N] [--reduction K] "
       "[--isa NAME] [-o FILE]"},
      [&arguments](tools::CommandLine& command_line) {
        command_line.description(
            "Draws a procedural city of box buildings and trees from street level, whole and\n"
            "with occlusion culling (the buildings as occluders), and compares the two.");
        tools::add_integer_option(command_line, "--width", arguments.width, 8, 8192,
                                  "image width (default 1280)");
        tools::add_integer_option(command_line, "--height", arguments.height, 8, 8192,
                                  "image height (default 720)");
        tools::add_integer_option(command_line, "--frames", arguments.frames, 1, 1000,
                                  "frames of each kind (default 7)");
        tools::add_integer_option(command_line, "--blocks", arguments.blocks, 1, 200,
                                  "blocks per side of the city (default 20: 1,600 buildings)");
        tools::add_integer_option(command_line, "--props", arguments.props, 0, 200,
                                  "trees per block (default 22)");
        tools::add_choice_option(
            command_line, "--reduction", {"1", "2", "4"},
            [&arguments](std::size_t i) { arguments.reduction = 1 << i; },
            "pixels per occlusion depth on each axis: 1 (exact, default), 2 or 4 (conservative)");
        tools::add_isa_options(command_line, arguments.isa,
                               "the ISA (default: the best of this CPU)",
                               "draw with the reference");
        tools::add_text_option(command_line, "-o", arguments.output,
                               "write the culled frame's image (PNG or EXR)")
            .type_name("FILE");
        return [&arguments] { return run(arguments); };
      });
}
