// Differential fuzz target for the occlusion queries (occlusion.hpp): the input bytes become a
// small view, occluder triangles under a camera, rectangles and boxes. Every supported ISA and the
// reference draw the occluders into their own OcclusionBuffer and answer every query. A finding
// prints the decoded input and the answers, then aborts, when:
// - the buffers' depths differ in any bit between ISAs;
// - a rectangle's answer differs from the brute force over the samples of its closed rectangle
//   (or an ISA throws where the brute force finds a bad rectangle, or the reverse);
// - a box's answer differs between an ISA and the reference;
// - a box is answered occluded while its twelve faces drawn with depth test less show a sample
//   (test_triangles(), the oracle), or outside while they cover one;
// - in buffers reduced 2 and 4 times (partial coverage ignored and merged): the blocks differ in
// any bit from the reference's, a block
//   lies below the full-resolution depth of one of its pixels, or a rectangle or box is answered
//   occluded where the full-resolution answer is visible, or outside where it is not.
//
// Input layout (missing bytes read as zero):
//   u8 width, u8 height            1 + v % 48 each
//   u8 camera                      % 3: clip space as given (w = 1), perspective, orthographic;
//                                  then for the two cameras 6 numbers: eye and target
//   u8 occluders % 9, then 9 numbers each (three corners)
//   u8 rectangles % 9, then 5 numbers each (x0, y0, x1, y1, depth)
//   u8 boxes % 9, then 6 numbers each (min, then max)
// A number is a u8 tag: < 200 an i16 / 512 (+-64 in 1/512 steps), else an entry of
// kSpecialValues (zeros, halves, the guard band's edge, float's extremes, NaN, infinities).
//
// Replay: `fuzz_occlusion <input file>` runs one input.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/edgewise.hpp"
#include "occlusion/box_faces.hpp"

namespace {

using namespace edgewise;
using test::box_faces;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kSpecialValues[] = {0.0f,
                                    -0.0f,
                                    0.5f,
                                    -0.5f,
                                    1.0f,
                                    -1.0f,
                                    32768.0f,
                                    -32768.0f,
                                    1e30f,
                                    1e-30f,
                                    kInf,
                                    -kInf,
                                    std::numeric_limits<float>::quiet_NaN(),
                                    0x1p-126f};

class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint8_t byte() { return position_ < bytes_.size() ? bytes_[position_++] : 0; }
  float number() {
    const std::uint8_t tag = byte();
    if (tag >= 200) return kSpecialValues[(tag - 200) % std::size(kSpecialValues)];
    const auto raw = static_cast<std::int16_t>(byte() | byte() << 8);
    return static_cast<float>(raw) / 512.0f;
  }
  Vec3 vec3() {
    const float x = number(), y = number();
    return {x, y, number()};
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t position_ = 0;
};

struct Input {
  std::int32_t width = 1, height = 1;
  Mat4 transform = identity();
  std::vector<Vec3> occluders;
  std::vector<OcclusionRect> rects;
  std::vector<OcclusionBox> boxes;
};

Input decode(std::span<const std::uint8_t> bytes) {
  Reader in(bytes);
  Input input;
  input.width = 1 + in.byte() % 48;
  input.height = 1 + in.byte() % 48;
  const int camera = in.byte() % 3;
  if (camera != 0) {
    const Vec3 eye = in.vec3(), target = in.vec3();
    const float aspect = static_cast<float>(input.width) / static_cast<float>(input.height);
    const bool degenerate =
        !(std::isfinite(eye.x) && std::isfinite(eye.y) && std::isfinite(eye.z) &&
          std::isfinite(target.x) && std::isfinite(target.y) && std::isfinite(target.z)) ||
        (eye.x == target.x && eye.z == target.z);
    if (!degenerate) {
      const Mat4 view = look_at(eye, target, {0.0f, 1.0f, 0.0f});
      input.transform = camera == 1 ? perspective(1.0f, aspect, 0.25f, 200.0f) * view
                                    : orthographic(-8.0f, 8.0f, -8.0f, 8.0f, 0.25f, 200.0f) * view;
    }
  }
  for (int n = in.byte() % 9, i = 0; i < 3 * n; ++i)
    input.occluders.push_back(in.vec3());
  for (int n = in.byte() % 9, i = 0; i < n; ++i) {
    OcclusionRect r;
    r.x0 = in.number();
    r.y0 = in.number();
    r.x1 = in.number();
    r.y1 = in.number();
    r.depth = in.number();
    input.rects.push_back(r);
  }
  for (int n = in.byte() % 9, i = 0; i < n; ++i) {
    const Vec3 low = in.vec3();
    input.boxes.push_back({low, in.vec3()});
  }
  return input;
}

// The brute force of a rectangle: its closed rectangle's samples read one by one; nullopt for a
// rectangle test_rects() must refuse.
std::optional<Visibility> brute_force(const std::vector<float>& depth, std::int32_t width,
                                      std::int32_t height, const OcclusionRect& r) {
  if (std::isnan(r.x0) || std::isnan(r.y0) || std::isnan(r.x1) || std::isnan(r.y1) ||
      std::isnan(r.depth) || r.x0 > r.x1 || r.y0 > r.y1) {
    return std::nullopt;
  }
  if (r.depth > 1.0f) return Visibility::outside;
  bool any = false;
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      if (cx < r.x0 || cx > r.x1 || cy < r.y0 || cy > r.y1) continue;
      any = true;
      if (depth[static_cast<std::size_t>(y) * width + x] > r.depth) return Visibility::visible;
    }
  }
  return any ? Visibility::occluded : Visibility::outside;
}

[[noreturn]] void finding(const Input& input, const std::string& what) {
  std::fprintf(stderr, "edgewise occlusion: %s\nview %dx%d, %zu occluder triangles:\n",
               what.c_str(), input.width, input.height, input.occluders.size() / 3);
  for (const Vec3& p : input.occluders)
    std::fprintf(stderr, "  (%a, %a, %a)\n", static_cast<double>(p.x), static_cast<double>(p.y),
                 static_cast<double>(p.z));
  for (const OcclusionRect& r : input.rects)
    std::fprintf(stderr, "rect [%a, %a] x [%a, %a] depth %a\n", static_cast<double>(r.x0),
                 static_cast<double>(r.x1), static_cast<double>(r.y0), static_cast<double>(r.y1),
                 static_cast<double>(r.depth));
  for (const OcclusionBox& b : input.boxes)
    std::fprintf(stderr, "box (%a, %a, %a) .. (%a, %a, %a)\n", static_cast<double>(b.min.x),
                 static_cast<double>(b.min.y), static_cast<double>(b.min.z),
                 static_cast<double>(b.max.x), static_cast<double>(b.max.y),
                 static_cast<double>(b.max.z));
  std::abort();
}

bool box_is_valid(const OcclusionBox& b) {
  const float v[6] = {b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z};
  for (const float c : v) {
    if (!std::isfinite(c)) return false;
  }
  return b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z;
}

// An answer on a reduced buffer that the full-resolution one contradicts: occluded where that is
// visible, or outside where that is not (or the reverse).
bool contradicts(Visibility reduced, Visibility full) {
  return (reduced == Visibility::outside) != (full == Visibility::outside) ||
         (reduced == Visibility::occluded && full == Visibility::visible);
}

// The reduced buffers of every ISA against the reference's, and against the full-resolution
// depth `full` and answers.
void check_reduced(const Input& input, std::int32_t k, PartialCoverage partial,
                   const std::vector<float>& full, const std::vector<OcclusionBox>& boxes,
                   const std::vector<Visibility>& full_boxes,
                   const std::vector<Visibility>& full_faces) {
  OcclusionOptions options;
  options.transform = input.transform;
  options.threads = 1;
  options.isa = Isa::reference;
  OcclusionBuffer reference(input.width, input.height, k, partial);
  reference.draw_occluders({input.occluders, {}}, options);
  std::vector<float> want(static_cast<std::size_t>(reference.depth_width()) *
                          reference.depth_height());
  reference.read_depth(want);
  const std::string reduced =
      "reduced " + std::to_string(k) + ", partial coverage " + std::string(name_of(partial)) + ": ";
  for (std::int32_t y = 0; y < input.height; ++y) {
    for (std::int32_t x = 0; x < input.width; ++x) {
      const float block = want[static_cast<std::size_t>(y / k) * reference.depth_width() + x / k];
      if (!(block >= full[static_cast<std::size_t>(y) * input.width + x]))
        finding(input, reduced + "block below the depth of pixel (" + std::to_string(x) + ", " +
                           std::to_string(y) + ")");
    }
  }
  std::vector<float> got(want.size());
  for (const Isa isa : supported_isas()) {
    options.isa = isa;
    OcclusionBuffer buffer(input.width, input.height, k, partial);
    buffer.draw_occluders({input.occluders, {}}, options);
    buffer.read_depth(got);
    for (std::size_t i = 0; i < want.size(); ++i) {
      if (std::bit_cast<std::uint32_t>(got[i]) != std::bit_cast<std::uint32_t>(want[i]))
        finding(input, reduced + std::string(name_of(isa)) + ": depth differs at block " +
                           std::to_string(i));
    }
    for (std::size_t i = 0; i < input.rects.size(); ++i) {
      const std::optional<Visibility> expected =
          brute_force(full, input.width, input.height, input.rects[i]);
      if (!expected) continue;  // refused, as at full resolution
      Visibility answer = Visibility::visible;
      buffer.test_rects(std::span(input.rects).subspan(i, 1), std::span(&answer, 1), isa);
      if (contradicts(answer, *expected))
        finding(input, reduced + std::string(name_of(isa)) + ": rectangle " + std::to_string(i));
    }
    std::vector<Visibility> answers(boxes.size());
    buffer.test_boxes(boxes, input.transform, answers, isa);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (contradicts(answers[i], full_boxes[i]))
        finding(input, reduced + std::string(name_of(isa)) + ": box " + std::to_string(i));
      const std::vector<Vec3> faces = box_faces(boxes[i]);
      options.isa = isa;
      const Visibility triangles = buffer.test_triangles({faces, {}}, options);
      if (contradicts(triangles, full_faces[i]))
        finding(input, reduced + std::string(name_of(isa)) + ": faces of box " + std::to_string(i));
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Input input = decode({data, size});
  OcclusionOptions options;
  options.transform = input.transform;
  options.threads = 1;
  // The reference first: its depth and answers are what every ISA must give.
  options.isa = Isa::reference;
  OcclusionBuffer reference(input.width, input.height);
  reference.draw_occluders({input.occluders, {}}, options);
  std::vector<float> want(static_cast<std::size_t>(input.width) * input.height);
  reference.read_depth(want);
  std::vector<OcclusionBox> valid_boxes;
  for (const OcclusionBox& b : input.boxes) {
    if (box_is_valid(b)) valid_boxes.push_back(b);
  }
  std::vector<Visibility> reference_boxes(valid_boxes.size());
  reference.test_boxes(valid_boxes, input.transform, reference_boxes, Isa::reference);
  std::vector<Visibility> face_oracles;
  for (std::size_t i = 0; i < valid_boxes.size(); ++i) {
    const std::vector<Vec3> faces = box_faces(valid_boxes[i]);
    const Visibility oracle = reference.test_triangles({faces, {}}, options);
    face_oracles.push_back(oracle);
    if (oracle == Visibility::visible && reference_boxes[i] != Visibility::visible)
      finding(input, "box " + std::to_string(i) + " hidden, but its faces show a sample");
    if (reference_boxes[i] == Visibility::outside && oracle != Visibility::outside)
      finding(input, "box " + std::to_string(i) + " outside, but its faces cover a sample");
  }
  std::vector<float> got(want.size());
  for (const Isa isa : supported_isas()) {
    options.isa = isa;
    OcclusionBuffer buffer(input.width, input.height);
    buffer.draw_occluders({input.occluders, {}}, options);
    buffer.read_depth(got);
    for (std::size_t i = 0; i < want.size(); ++i) {
      if (std::bit_cast<std::uint32_t>(got[i]) != std::bit_cast<std::uint32_t>(want[i]))
        finding(input, std::string(name_of(isa)) + ": depth differs at pixel " + std::to_string(i));
    }
    for (std::size_t i = 0; i < input.rects.size(); ++i) {
      const std::optional<Visibility> expected =
          brute_force(want, input.width, input.height, input.rects[i]);
      Visibility answer = Visibility::visible;
      bool refused = false;
      try {
        buffer.test_rects(std::span(input.rects).subspan(i, 1), std::span(&answer, 1), isa);
      } catch (const std::invalid_argument&) {
        refused = true;
      }
      if (refused != !expected.has_value() || (expected && answer != *expected))
        finding(input, std::string(name_of(isa)) + ": rectangle " + std::to_string(i));
    }
    std::vector<Visibility> boxes(valid_boxes.size());
    buffer.test_boxes(valid_boxes, input.transform, boxes, isa);
    if (boxes != reference_boxes) finding(input, std::string(name_of(isa)) + ": box answers");
  }
  for (const std::int32_t k : {2, 4}) {
    for (const PartialCoverage partial : values_of<PartialCoverage>())
      check_reduced(input, k, partial, want, valid_boxes, reference_boxes, face_oracles);
  }
  return 0;
}
