#include "atlas/aa_study.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "aa_accuracy/coverage_modes.hpp"
#include "edgewise/edgewise.hpp"

namespace edgewise::atlas {

StudyOutput aa_study(const StudySettings& settings, const std::string& cpu) {
  using namespace tools;
  StudyOutput out("aa", "Anti-aliasing: coverage modes against the exact area", cpu);
  constexpr const char* kPareto = "aa-pareto";
  constexpr const char* kSamples = "aa-samples";
  out.add_chart({kPareto, "Coverage error at edge pixels against time per triangle",
                 "ns per triangle (random triangles 4 to 64 px across, 256x256)",
                 "mean |coverage - exact area| at edge pixels (px^2)", true, true,
                 ChartKind::scatter, ""});
  out.add_chart({kSamples, "Coverage error by samples per pixel", "samples per pixel",
                 "error against the exact area (px^2)", true, true, ChartKind::line, ""});
  const std::size_t count = settings.quick ? 50 : 2000;
  const std::vector<Vec2> triangles = random_aa_triangles(count, 1);
  const std::vector<Vec2> star = siemens_star(64);
  const ModeErrors errors = measure_modes(triangles, star, active_isa());
  double exact_ns = 0.0, four_ns = 0.0;
  for (int m = 0; m < kAaModes; ++m) {
    for (Isa isa : supported_isas()) {
      const double ns = median_nanoseconds(
                            "aa/" + aa_mode_name(m) + "/" + std::string(name_of(isa)),
                            [&] { coverage_image(triangles, m, isa); }, settings.timer) /
                        static_cast<double>(count);
      out.add(kPareto, aa_mode_name(m), ns, errors.edge[m].mean(), std::string(name_of(isa)));
      if (isa == active_isa() && kAaSamples[m] == 0) exact_ns = ns;
      if (isa == active_isa() && kAaSamples[m] == 4) four_ns = ns;
    }
    if (kAaSamples[m] > 0) {
      out.add(kSamples, "edge pixels, mean", kAaSamples[m], errors.edge[m].mean());
      out.add(kSamples, "edge pixels, worst", kAaSamples[m], errors.edge[m].worst);
      out.add(kSamples, "Siemens star, RMSE", kAaSamples[m], errors.image_rmse[m]);
    }
  }
  char reading[400];
  std::snprintf(reading, sizeof reading,
                "Lower left is better. The exact area (error %.1e, its float rounding) costs "
                "%.2fx the time of 4 samples on %s here, including building each image; 4 "
                "samples miss the edge pixels' area by %.3f px^2 on average.",
                errors.edge[kAaModes - 1].mean(), exact_ns / four_ns,
                std::string(name_of(active_isa())).c_str(), errors.edge[2].mean());
  out.set_reading(kPareto, reading);
  std::snprintf(reading, sizeof reading,
                "Each doubling of the samples cuts the mean edge error by about %.2fx (1 to 16 "
                "samples: %.3f to %.3f px^2); the worst edge pixel falls from %.2f to %.2f.",
                std::pow(errors.edge[0].mean() / errors.edge[4].mean(), 0.25),
                errors.edge[0].mean(), errors.edge[4].mean(), errors.edge[0].worst,
                errors.edge[4].worst);
  out.set_reading(kSamples, reading);
  return out;
}

}  // namespace edgewise::atlas
