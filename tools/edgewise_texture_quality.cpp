// edgewise-texture-quality: the accuracy half of "speed and accuracy, charted against each
// other". Scores every texture filter (each ISA asked for, and OpenImageIO's TextureSystem as a
// peer) against ground truth on the scored scenes, with the time per sample beside each error,
// and marks the Pareto front. tools/plot_texture_quality.py charts its CSV.
//
// Timing: the median over --repeat runs of one sample() call over the whole screen (one thread),
// the peer's lookups timed the same way; with --draw, of one clear and draw() of the view's mesh.
// These are this tool's figures, for placing the methods against each other; the benchmark suite
// gives the official throughput.
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/median.hpp"
#include "common/progress.hpp"
#include "common/run_tool.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "texture_quality/command_line.hpp"
#include "texture_quality/drawn_view.hpp"
#include "texture_quality/filter_methods.hpp"
#include "texture_quality/ground_truth_store.hpp"
#include "texture_quality/oiio_peer.hpp"
#include "texture_quality/pareto_front.hpp"
#include "texture_quality/result_images.hpp"
#include "texture_quality/scenes.hpp"
#include "texture_quality/score_csv.hpp"
#include "texture_quality/score_row.hpp"
#include "texture_quality/score_table.hpp"
#include "texture_quality/writable_directory.hpp"
#include "texture_scene/image_metrics.hpp"
#include "texture_scene/linear_image.hpp"

namespace {

using namespace edgewise;
using namespace edgewise::texture_quality;
using tools::median_seconds;

// Everything a scene's methods share: its queries, ground truth and where its pictures go.
struct SceneRun {
  std::string texture, view, size;
  std::vector<TextureQuery> queries;
  texture_scene::LinearImage truth;
  std::optional<std::filesystem::path> images;

  std::filesystem::path image_path(const std::string& suffix) const {
    return *images / (texture + "_" + view + "_" + size + "_" + suffix + ".png");
  }

  // The row of a method whose results are in `colours`, taking `seconds` per run; writes its
  // pictures when asked to.
  ScoreRow score(const std::string& method, std::string_view isa, std::span<const Vec4> colours,
                 double seconds) const {
    const texture_scene::LinearImage result =
        texture_scene::image_from_samples(truth.width, truth.height, colours);
    const texture_scene::ImageError error = texture_scene::compare_images(result, truth);
    if (images) {
      const std::string name = method + "_" + std::string(isa);
      write_srgb_png(image_path(name), result);
      write_srgb_png(image_path(name + "_error"), error_image(result, truth));
    }
    ScoreRow row;
    row.texture = texture;
    row.view = view;
    row.size = size;
    row.method = method;
    row.isa = std::string(isa);
    row.rmse = error.rmse;
    row.psnr = error.psnr;
    row.worst = error.worst;
    row.ns_per_sample = seconds / static_cast<double>(queries.size()) * 1e9;
    return row;
  }
};

void mark_pareto_front(std::span<ScoreRow> rows) {
  std::vector<CostAndError> points;
  for (const ScoreRow& row : rows)
    points.push_back({row.ns_per_sample, row.rmse});
  const std::vector<bool> front = pareto_front(points);
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows[i].pareto = front[i];
}

std::string isa_list(std::span<const Isa> isas) {
  std::string text;
  for (Isa isa : isas)
    text += (text.empty() ? "" : ", ") + std::string(name_of(isa));
  return text;
}

// Every method on every ISA (sampled, and drawn when `drawn` is given), then the peer's modes,
// each timed over the whole screen.
std::vector<ScoreRow> score_scene(const SceneRun& scene, const Texture& texture, OiioPeer* peer,
                                  DrawnView* drawn, std::span<const Isa> isas,
                                  std::span<const FilterMethod> methods, int repetitions) {
  std::vector<Vec4> colours(scene.queries.size());
  std::vector<ScoreRow> rows;
  const std::size_t runs_per_isa = methods.size() * (drawn != nullptr ? 3 : 1);
  tools::Progress progress(
      "  scoring",
      static_cast<std::int64_t>(isas.size() * runs_per_isa +
                                (peer != nullptr ? std::size(kPeerModeNames) : 0)),
      "methods");
  const auto add_row = [&](ScoreRow row) {
    rows.push_back(std::move(row));
    progress.update(static_cast<std::int64_t>(rows.size()));
  };
  for (Isa isa : isas) {
    for (const FilterMethod& method : methods) {
      const double seconds = median_seconds(repetitions, [&] {
        sample(texture, {method.options, isa}, scene.queries, colours);
      });
      add_row(scene.score(method.name, name_of(isa), colours, seconds));
    }
    if (drawn == nullptr) continue;
    for (TextureDerivatives derivatives :
         {TextureDerivatives::quad, TextureDerivatives::analytic}) {
      for (const FilterMethod& method : methods) {
        const double seconds = median_seconds(
            repetitions, [&] { drawn->draw(texture, method.options, derivatives, isa); });
        drawn->read(colours);
        const std::string name = "draw_" + std::string(name_of(derivatives)) + "_" + method.name;
        add_row(scene.score(name, name_of(isa), colours, seconds));
      }
    }
  }
  if (peer != nullptr) {
    for (std::size_t mode = 0; mode < std::size(kPeerModeNames); ++mode) {
      const double seconds =
          median_seconds(repetitions, [&] { peer->sample(mode, scene.queries, colours); });
      add_row(scene.score("oiio_" + std::string(kPeerModeNames[mode]), "oiio", colours, seconds));
    }
  }
  progress.finish();
  return rows;
}

void print_preamble(const QualitySettings& settings, const std::string& size,
                    std::span<const Isa> isas, const std::optional<std::filesystem::path>& images) {
  std::cout << "edgewise-texture-quality: " << size << " screen, ISA " << isa_list(isas)
            << (settings.peer ? " and OpenImageIO's TextureSystem" : "") << ", "
            << name_of(settings.pyramid) << " pyramid, max anisotropy "
            << settings.methods.max_anisotropy << ", level of detail "
            << name_of(settings.methods.lod) << " with bias " << settings.methods.lod_bias
            << ", repeat wrap\n"
            << "  errors: against ground truth, linear units over R, G, B; front: '*' marks the "
               "Pareto front (lowest RMSE for its time)\n"
            << "  times: this tool's, the median of " << settings.repetitions
            << " runs of sample() over the whole view, one thread; the benchmark suite "
               "(edgewise-bench), not this tool, gives the official figures\n";
  if (images) {
    std::cout << "  images: " << images->string()
              << ", PNG, linear values clamped to [0, 1] and written sRGB-encoded for viewing; "
                 "errors are |result - truth| x "
              << kErrorImageGain << '\n';
  }
}

int run(const QualitySettings& settings) {
  const std::vector<Isa> isas = resolve_isas(settings);
  const std::vector<FilterMethod> methods = filter_methods(settings.methods);

  // Every output is checked before the first ground truth, which may take minutes.
  const std::filesystem::path cache = settings.cache_directory
                                          ? std::filesystem::path(*settings.cache_directory)
                                          : default_cache_directory();
  prepare_writable_directory(cache);
  std::optional<ScoreCsvFile> csv;
  if (settings.csv_path) csv.emplace(*settings.csv_path);
  std::optional<std::filesystem::path> images;
  if (settings.images_directory) {
    images = *settings.images_directory;
    prepare_writable_directory(*images);
  }

  const std::string size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
  print_preamble(settings, size, isas, images);

  std::vector<ScoreRow> all_rows;
  for (SceneTexture scene_texture_choice : settings.textures) {
    const texture_scene::LinearImage image =
        scene_texture_image(scene_texture_choice, settings.texture_size);
    const Texture texture = scene_texture(image, settings.pyramid);
    const std::string texture_name(scene_texture_name(scene_texture_choice));
    std::optional<OiioPeer> peer;
    if (settings.peer) peer.emplace(image, texture_name + std::to_string(settings.texture_size));

    for (SceneView scene_view_choice : settings.views) {
      const texture_scene::TextureView view =
          scene_view(scene_view_choice, settings.width, settings.height, settings.texture_size);
      SceneRun scene;
      scene.texture = texture_name;
      scene.view = std::string(scene_view_name(scene_view_choice));
      scene.size = size;
      scene.images = images;
      std::cout << '\n'
                << scene_texture_description(scene_texture_choice, settings.texture_size) << " / "
                << scene.view << " " << size << '\n';
      StoredGroundTruth stored = load_or_compute_ground_truth(
          cache,
          texture_name + std::to_string(settings.texture_size) + "_" + scene.view + "_" + size,
          image, view, std::cout);
      scene.truth = std::move(stored.truth.image);
      scene.queries = view.queries();
      if (images) write_srgb_png(scene.image_path("ground_truth"), scene.truth);

      std::optional<DrawnView> drawn;
      if (settings.draw) drawn.emplace(view);
      std::vector<ScoreRow> rows =
          score_scene(scene, texture, peer ? &*peer : nullptr, drawn ? &*drawn : nullptr, isas,
                      methods, settings.repetitions);
      mark_pareto_front(rows);
      print_score_table(std::cout, rows);
      all_rows.insert(all_rows.end(), rows.begin(), rows.end());
    }
  }
  if (csv) {
    csv->write(all_rows);
    std::cout << "\nscores written to " << *settings.csv_path << '\n';
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  QualitySettings settings;
  return tools::run_tool(argc, argv, "edgewise-texture-quality", usage_lines(),
                         [&settings](tools::CommandLine& command_line) {
                           add_options(command_line, settings);
                           return [&settings] { return run(settings); };
                         });
}
