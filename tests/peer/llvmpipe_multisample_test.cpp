// 4x multisampled coverage against an independent rasterizer, Mesa's llvmpipe, through OpenGL
// (docs/design/anti-aliasing.md): the same triangles (sample_edge_triangles.hpp), each in a
// colour of its own, drawn in order without depth test by both, must leave every sample of every
// pixel with the same triangle, on every ISA. Many samples lie exactly on edges, where only the
// fill rule decides (tie_rules.hpp counts them).
//
// The frames. edgewise's screen has y down, pixel (x, y) is [x, x + 1) x [y, y + 1), the samples
// are at the standard offsets (y down) and ties follow the top-left rule. GL's window y is up by
// default (GL_LOWER_LEFT). Each vertex goes to GL with its clip y negated (y_ndc = 2 y / H - 1 in
// place of edgewise's 1 - 2 y / H), so that its window y is edgewise's screen y: GL's pixel row y
// (in the texture's memory and in glReadPixels) is edgewise's row y, nothing mirrored between.
// In that one frame:
//  - Sample positions: glGetMultisamplefv(GL_SAMPLE_POSITION) gives each sample's position in
//    its pixel in window coordinates; edgewise's sample k is compared with the GL sample at
//    ((8 + dx) / 16, (8 + dy) / 16), and the test fails if there is none. llvmpipe (Mesa 22.3.6)
//    reports (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875): the standard
//    pattern, in its order.
//  - Fill rule: llvmpipe gives a sample exactly on a horizontal edge to the triangle at the
//    larger window y, and one on a sloped edge to the triangle at the larger x, which in this
//    frame is the top-left rule: no sample differs from the exact rule of tie_rules.hpp.
// glClipControl(GL_UPPER_LEFT) makes the same window y without negating y, but Mesa then gives
// horizontal-edge ties to the triangle at the smaller y: measured, llvmpipe then differs from
// edgewise at exactly the samples where the bottom-left rule and the top-left rule disagree. So
// the test keeps GL's default origin and negates y.
#include <gtest/gtest.h>

#include <array>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/framebuffer.hpp"
#include "edgewise/multisample.hpp"
#include "gl_multisample_ids.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "sample_edge_triangles.hpp"
#include "gl/surfaceless_gl.hpp"
#include "tie_rules.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kWidth = 256, kHeight = 256;
constexpr int kSamples = 4;
constexpr int kFrames = 24;
constexpr int kShapesPerFrame = 250;
constexpr std::uint64_t kSeed = 20261203;

// Triangle t's colour: 1 + t in the 24 bits of R, G and B (never 0, the cleared value), opaque.
// Back from a colour: 1 + t, or 0 where no triangle covers the sample.
std::uint32_t color_of(std::size_t t) {
  return std::uint32_t(t + 1) | 0xff000000u;
}
std::uint32_t triangle_of(std::uint32_t color) {
  return color & 0x00ffffffu;
}

struct Frame {
  std::vector<FixedTriangle> triangles;
  TieRuleImages exact;  // the triangle of each sample under each fill rule
};

const std::vector<Frame>& frames() {
  static const std::vector<Frame> all = [] {
    Random random(kSeed);
    const auto pattern = standard_sample_pattern(kSamples);
    std::vector<Frame> made(kFrames);
    for (Frame& frame : made) {
      frame.triangles = sample_edge_triangles(random, kWidth, kHeight, pattern, kShapesPerFrame);
      frame.exact = tie_rule_images(frame.triangles, kWidth, kHeight, pattern);
    }
    return made;
  }();
  return all;
}

// Clip coordinates (w = 1) of a screen point of a kWidth x kHeight target, exact in float: the
// 1/256 px grid is preserved. edgewise's viewport puts NDC y = 1 at the top (screen y = 0).
Vec2 edgewise_clip(const FixedPoint& p) {
  return {float(double(p.x) / (kFixedOne / 2 * kWidth) - 1.0),
          float(1.0 - double(p.y) / (kFixedOne / 2 * kHeight))};
}
// The same point for GL, whose default lower-left origin then makes window y = screen y.
Vec2 gl_clip(const FixedPoint& p) {
  return {float(double(p.x) / (kFixedOne / 2 * kWidth) - 1.0),
          float(double(p.y) / (kFixedOne / 2 * kHeight) - 1.0)};
}

struct LlvmpipeRun {
  std::string skip;   // why llvmpipe could not be run here
  std::string error;  // what went wrong once it ran: a failure
  std::string renderer;
  std::array<int, kSamples> gl_sample{};  // edgewise's sample k is GL's sample gl_sample[k]
  std::vector<std::vector<std::uint32_t>> samples;  // per frame (gl_multisample_ids.hpp)
};

std::string describe(const std::vector<Vec2>& positions) {
  std::string text;
  for (const Vec2& p : positions) {
    text += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
  }
  return text;
}

// For each of edgewise's samples k, the GL sample gl_sample[k] at the same offset from the pixel
// centre, in the frame the geometry is given in (window y = edgewise's screen y); or why none.
std::string match_samples(const std::vector<Vec2>& positions,
                          std::array<int, kSamples>& gl_sample) {
  const auto pattern = standard_sample_pattern(kSamples);
  std::array<bool, kSamples> taken{};
  for (int k = 0; k < kSamples; ++k) {
    gl_sample[k] = -1;
    for (int g = 0; g < int(positions.size()); ++g) {
      if (!taken[g] && positions[g].x * 16 - 8 == pattern[k].x &&
          positions[g].y * 16 - 8 == pattern[k].y) {
        gl_sample[k] = g;
        taken[g] = true;
      }
    }
    if (gl_sample[k] < 0) {
      return "GL's sample positions," + describe(positions) +
             ", are not the standard 4x pattern in edgewise's frame: none is at (" +
             std::to_string((8 + pattern[k].x) / 16.0) + ", " +
             std::to_string((8 + pattern[k].y) / 16.0) + ") for edgewise's sample " +
             std::to_string(k);
    }
  }
  return {};
}

LlvmpipeRun run_llvmpipe() {
  LlvmpipeRun run;
  std::string why_not;
  const auto gl = gl::SurfacelessGl::create(why_not);
  if (!gl) {
    run.skip = "no OpenGL context on EGL's surfaceless platform: " + why_not;
    return run;
  }
  run.renderer = gl->renderer();
  if (run.renderer.rfind("llvmpipe", 0) != 0) {
    run.skip = "GL_RENDERER is \"" + run.renderer + "\", not llvmpipe";
    return run;
  }
  const auto target = GlMultisampleIds::create(kWidth, kHeight, kSamples, why_not);
  if (!target) {
    run.error = run.renderer + ": " + why_not;
    return run;
  }
  run.error = match_samples(target->sample_positions(), run.gl_sample);
  if (!run.error.empty()) return run;
  for (const Frame& frame : frames()) {
    std::vector<Vec2> clip;
    std::vector<std::uint32_t> colors;
    for (std::size_t t = 0; t < frame.triangles.size(); ++t) {
      for (const FixedPoint& p : frame.triangles[t])
        clip.push_back(gl_clip(p));
      colors.push_back(color_of(t));
    }
    run.samples.push_back(target->draw(clip, colors, why_not));
    if (run.samples.back().empty()) {
      run.error = run.renderer + ": " + why_not;
      return run;
    }
  }
  return run;
}

const LlvmpipeRun& llvmpipe() {
  static const LlvmpipeRun run = run_llvmpipe();
  return run;
}

std::string describe(const FixedTriangle& t) {
  std::string text;
  for (const FixedPoint& p : t) {
    text += " (" + std::to_string(p.x / double(kFixedOne)) + ", " +
            std::to_string(p.y / double(kFixedOne)) + ")";
  }
  return text;
}

std::string describe_triangle(const Frame& frame, std::uint32_t id) {
  if (id == 0) return "none";
  if (id > frame.triangles.size()) return std::to_string(id) + " (no such triangle)";
  return std::to_string(id - 1) + ":" + describe(frame.triangles[id - 1]);
}

// The frame drawn by edgewise on `isa`: for each sample, 1 + the index of its triangle, or 0;
// sample k of pixel (x, y) is element (k * kHeight + y) * kWidth + x.
std::vector<std::uint32_t> edgewise_triangles(Isa isa, const Frame& frame) {
  std::vector<Vec3> positions;
  std::vector<Vec4> colors;
  for (std::size_t t = 0; t < frame.triangles.size(); ++t) {
    const std::uint32_t c = color_of(t);
    const Vec4 color{float(c & 0xff) / 255, float(c >> 8 & 0xff) / 255, float(c >> 16 & 0xff) / 255,
                     float(c >> 24) / 255};
    for (const FixedPoint& p : frame.triangles[t]) {
      const Vec2 xy = edgewise_clip(p);
      positions.push_back({xy.x, xy.y, 0.5f});
      colors.push_back(color);
    }
  }
  Framebuffer target(kWidth, kHeight, kSamples);
  target.clear({0.0f, 0.0f, 0.0f, 0.0f}, 1.0f);
  DrawOptions options;
  options.depth_test = DepthTest::always;
  options.depth_write = false;
  options.shading = Shading::flat;
  options.isa = isa;
  options.threads = 1;
  DrawMesh mesh;
  mesh.positions = positions;
  mesh.colors = colors;
  const DrawReport report = draw(target, mesh, options);
  EXPECT_EQ(report.errors, 0u);
  EXPECT_EQ(report.clipped, 0u);  // every vertex inside the target

  const std::size_t plane = std::size_t(kWidth) * kHeight;
  std::vector<std::uint8_t> rgba(plane * 4);
  std::vector<std::uint32_t> triangles(plane * kSamples);
  for (int k = 0; k < kSamples; ++k) {
    target.read_rgba8(rgba, k);
    for (std::size_t pixel = 0; pixel < plane; ++pixel) {
      triangles[std::size_t(k) * plane + pixel] =
          triangle_of(std::uint32_t(rgba[4 * pixel]) | std::uint32_t(rgba[4 * pixel + 1]) << 8 |
                      std::uint32_t(rgba[4 * pixel + 2]) << 16);
    }
  }
  return triangles;
}

using LlvmpipeMultisample = IsaTest;

TEST_P(LlvmpipeMultisample, EverySampleHoldsTheSameTriangle) {
  const LlvmpipeRun& gl = llvmpipe();
  if (!gl.skip.empty()) GTEST_SKIP() << gl.skip;
  ASSERT_TRUE(gl.error.empty()) << gl.error;
  const std::size_t plane = std::size_t(kWidth) * kHeight;
  std::uint64_t compared = 0, mismatches = 0, on_edge = 0, decided = 0;
  for (std::size_t f = 0; f < frames().size(); ++f) {
    const Frame& frame = frames()[f];
    const std::vector<std::uint32_t> ours = edgewise_triangles(isa(), frame);
    on_edge += frame.exact.on_edge;
    for (int k = 0; k < kSamples; ++k) {
      for (std::size_t pixel = 0; pixel < plane; ++pixel) {
        const std::size_t at = std::size_t(k) * plane + pixel;
        const std::uint32_t edgewise = ours[at];
        const std::uint32_t llvmpipe =
            triangle_of(gl.samples[f][std::size_t(gl.gl_sample[k]) * plane + pixel]);
        const bool tie = frame.exact.decided_by_fill_rule(at);
        decided += tie ? 1 : 0;
        ++compared;
        if (edgewise == llvmpipe) continue;
        if (++mismatches <= 10) {
          ADD_FAILURE() << "frame " << f << ", pixel (" << pixel % kWidth << ", " << pixel / kWidth
                        << "), sample " << k << " (GL's " << gl.gl_sample[k]
                        << "): edgewise has triangle " << describe_triangle(frame, edgewise)
                        << ", llvmpipe " << describe_triangle(frame, llvmpipe)
                        << ", the exact top-left rule "
                        << describe_triangle(frame, frame.exact.ids[0][at])
                        << (tie ? " (the fill rule decides)" : "");
        }
      }
    }
  }
  EXPECT_EQ(mismatches, 0u) << "of " << compared << " samples";
  std::string order;
  for (int g : gl.gl_sample) {
    order += ' ';  // appended apart: GCC 12 warns falsely of overlap in " " + std::string
    order += std::to_string(g);
  }
  std::printf("%s against %s (edgewise's samples 0-3 are GL's%s): %" PRIu64
              " samples compared, %" PRIu64 " differ; %" PRIu64
              " (triangle, sample) pairs exactly on an edge, %" PRIu64
              " samples decided by the fill rule\n",
              std::string(name_of(isa())).c_str(), gl.renderer.c_str(), order.c_str(), compared,
              mismatches, on_edge, decided);
  RecordProperty("samples_compared", std::to_string(compared));
  RecordProperty("mismatches", std::to_string(mismatches));
  RecordProperty("samples_on_edges", std::to_string(on_edge));
  RecordProperty("samples_decided_by_fill_rule", std::to_string(decided));
}

EDGEWISE_INSTANTIATE_PER_ISA(LlvmpipeMultisample, every_isa());

// The frames tell the fill rules apart: a rasterizer that broke ties by any mirror image of the
// top-left rule would differ from edgewise at some samples, so agreeing everywhere checks the rule.
TEST(LlvmpipeMultisampleFrames, TellEveryMirroredFillRuleApart) {
  std::uint64_t on_edge = 0;
  std::array<std::uint64_t, kTieRules.size()> differ{};
  for (const Frame& frame : frames()) {
    on_edge += frame.exact.on_edge;
    for (std::size_t r = 1; r < kTieRules.size(); ++r) {
      differ[r] += frame.exact.differing_samples(kTieRules[r]);
    }
  }
  EXPECT_GT(on_edge, 0u);
  std::printf("%" PRIu64
              " (triangle, sample) pairs exactly on an edge; samples the top-left rule "
              "gives another triangle than",
              on_edge);
  for (std::size_t r = 1; r < kTieRules.size(); ++r) {
    EXPECT_GT(differ[r], 0u) << name_of(kTieRules[r]);
    std::printf("%s the %s rule: %" PRIu64, r > 1 ? "," : "", name_of(kTieRules[r]), differ[r]);
    RecordProperty(std::string("differ_from_") + name_of(kTieRules[r]), std::to_string(differ[r]));
  }
  std::printf("\n");
}

}  // namespace
}  // namespace edgewise::test
