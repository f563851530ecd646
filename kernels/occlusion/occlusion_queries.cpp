// OcclusionBuffer's rectangle and box queries (occlusion.hpp): the occlusion kernels turn each
// chunk of queries into ranges of samples and compare those with the depths, on one thread or on
// ranges of the list, one task each.
#include "edgewise/occlusion.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "../core/kernel_table.hpp"
#include "../core/parallel.hpp"
#include "../draw/vertex_stage/clip.hpp"
#include "query_bounds.hpp"

namespace edgewise {
namespace {

void check_answers(std::size_t queries, std::size_t answers, const char* caller) {
  if (queries != answers) {
    throw std::invalid_argument(std::string(caller) + ": " + std::to_string(answers) +
                                " answers for " + std::to_string(queries) + " queries");
  }
}

// Queries turned into sample ranges at a time: on the stack, and few enough to stay in L1.
constexpr std::size_t kQueriesPerChunk = 256;

// Queries per task when a query call runs on several threads: enough that a task's start costs
// little beside its queries (tens of nanoseconds each).
constexpr std::size_t kQueriesPerTask = 2048;

// What the queries read: the buffer's depth, and the view it stands for.
struct QueryView {
  detail::OcclusionDepth depth;
  std::int32_t width, height, reduction;
};

// Rectangles [first, last) answered into `out`, a chunk at a time; returns `last`, or the index
// of the first rectangle rect_samples() rejects (its chunk then left unanswered).
std::size_t answer_rects(const detail::KernelTable& kernels, const QueryView& view,
                         std::span<const OcclusionRect> rects, std::span<Visibility> out,
                         std::size_t first, std::size_t last) {
  std::array<detail::SampleRect, kQueriesPerChunk> samples;
  for (std::size_t begin = first; begin < last; begin += kQueriesPerChunk) {
    const std::size_t count = std::min(kQueriesPerChunk, last - begin);
    const std::size_t valid = kernels.rect_sample_ranges(
        rects.data() + begin, count, view.width, view.height, view.reduction, samples.data());
    if (valid < count) return begin + valid;
    kernels.test_sample_rects(view.depth, samples.data(), count, out.data() + begin);
  }
  return last;
}

// The same for boxes under `transform`, whose first rejected one box_samples() would reject.
std::size_t answer_boxes(const detail::KernelTable& kernels, const QueryView& view,
                         const Mat4& transform, const GuardBandPlanes& planes,
                         std::span<const OcclusionBox> boxes, std::span<Visibility> out,
                         std::size_t first, std::size_t last) {
  const Viewport viewport{view.width, view.height};
  std::array<detail::BoxSamples, kQueriesPerChunk> bounds;
  std::array<detail::SampleRect, kQueriesPerChunk> samples;
  for (std::size_t begin = first; begin < last; begin += kQueriesPerChunk) {
    const std::size_t count = std::min(kQueriesPerChunk, last - begin);
    const std::size_t valid = kernels.box_sample_ranges(boxes.data() + begin, count, transform,
                                                        viewport, planes, bounds.data());
    if (valid < count) return begin + valid;
    for (std::size_t i = 0; i < count; ++i) {
      // Empty, so outside, unless bounded.
      samples[i] = detail::sample_blocks(bounds[i].samples, view.reduction);
    }
    kernels.test_sample_rects(view.depth, samples.data(), count, out.data() + begin);
    for (std::size_t i = 0; i < count; ++i) {
      if (bounds[i].reach == detail::BoxReach::unbounded) out[begin + i] = Visibility::visible;
    }
  }
  return last;
}

// answer(first, last) over queries [0, count), in ranges on `workers`; returns the least index a
// range stopped at, or `count`. Each answer is its query's alone, so they are the same for every
// thread count, and so is the query named when one is rejected: the first of the list.
template <class Answer>
std::size_t answer_in_ranges(std::size_t count, const detail::Workers& workers,
                             const Answer& answer) {
  const std::size_t tasks =
      std::min(workers.threads, (count + kQueriesPerTask - 1) / kQueriesPerTask);
  if (tasks <= 1) return answer(std::size_t{0}, count);
  std::vector<std::size_t> stopped(tasks);
  workers.run(tasks, [&](std::size_t task) {
    const std::size_t first = count / tasks * task + std::min(task, count % tasks);
    const std::size_t last = first + count / tasks + (task < count % tasks ? 1 : 0);
    const std::size_t at = answer(first, last);
    stopped[task] = at < last ? at : count;
  });
  return *std::min_element(stopped.begin(), stopped.end());
}

}  // namespace

void OcclusionBuffer::test_rects(std::span<const OcclusionRect> rects, std::span<Visibility> out,
                                 std::optional<Isa> isa) const {
  OcclusionOptions options;
  options.isa = isa;
  options.threads = 1;
  test_rects(rects, out, options);
}

void OcclusionBuffer::test_rects(std::span<const OcclusionRect> rects, std::span<Visibility> out,
                                 const OcclusionOptions& options) const {
  check_answers(rects.size(), out.size(), "test_rects");
  const detail::KernelTable& kernels = detail::kernel_table(resolve_isa(options.isa));
  const QueryView view{
      {depth_.depth_tiles(), tile_max_.data(), depth_.tiles_x()}, width(), height(), reduction_};
  const std::size_t rejected = answer_in_ranges(
      rects.size(), detail::resolve_workers(options.threads, options.executor, "test_rects"),
      [&](std::size_t first, std::size_t last) {
        return answer_rects(kernels, view, rects, out, first, last);
      });
  // rect_samples() throws for it, naming it and the reason.
  if (rejected < rects.size()) detail::rect_samples(rects[rejected], width(), height(), rejected);
}

void OcclusionBuffer::test_boxes(std::span<const OcclusionBox> boxes, const Mat4& transform,
                                 std::span<Visibility> out, std::optional<Isa> isa) const {
  OcclusionOptions options;
  options.transform = transform;
  options.isa = isa;
  options.threads = 1;
  test_boxes(boxes, out, options);
}

void OcclusionBuffer::test_boxes(std::span<const OcclusionBox> boxes, std::span<Visibility> out,
                                 const OcclusionOptions& options) const {
  check_answers(boxes.size(), out.size(), "test_boxes");
  const detail::KernelTable& kernels = detail::kernel_table(resolve_isa(options.isa));
  const QueryView view{
      {depth_.depth_tiles(), tile_max_.data(), depth_.tiles_x()}, width(), height(), reduction_};
  const Viewport viewport{width(), height()};
  const GuardBandPlanes planes = guard_band_planes(viewport);
  const std::size_t rejected = answer_in_ranges(
      boxes.size(), detail::resolve_workers(options.threads, options.executor, "test_boxes"),
      [&](std::size_t first, std::size_t last) {
        return answer_boxes(kernels, view, options.transform, planes, boxes, out, first, last);
      });
  // box_samples() throws for it, naming it and the reason.
  if (rejected < boxes.size())
    detail::box_samples(boxes[rejected], options.transform, viewport, planes, rejected);
}

}  // namespace edgewise
