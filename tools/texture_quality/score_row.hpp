// One scored method in one scene: its error against the ground truth and its time per sample.
#pragma once

#include <string>

namespace edgewise::texture_quality {

struct ScoreRow {
  std::string texture;  // "checkerboard", "sinusoids"
  std::string view;     // "ground_plane", "magnification"
  std::string size;     // the screen, "480x270"
  std::string method;   // "trilinear", "ewa_16x", "oiio_trilinear"
  std::string isa;      // "avx2", "reference", or "oiio" for OpenImageIO's TextureSystem
  double rmse = 0.0;    // linear units over R, G, B (texture_scene/image_metrics.hpp)
  double psnr = 0.0;    // dB, peak 1
  double worst = 0.0;   // the largest absolute error of one channel
  double ns_per_sample = 0.0;
  bool pareto = false;  // on its scene's Pareto front (RMSE against ns per sample)

  bool operator==(const ScoreRow&) const = default;
};

}  // namespace edgewise::texture_quality
