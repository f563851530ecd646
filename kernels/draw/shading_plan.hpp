// The shading phase's plan for a binned draw (phases 2 and 3 of docs/design/threads.md): every
// bin a task, crowded bins cut into sub-bins with their triangles binned again, the tasks dealt
// costliest first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "../coverage/bin_grid.hpp"
#include "draw_stages.hpp"
#include "shading/shade_batch.hpp"
#include "../coverage/triangle_binning.hpp"

namespace edgewise::detail {

// The dealing order's keys: a task's load above its index, so that sorting 64-bit integers puts
// the costliest first and, among equal loads, the earlier bin first (a stable sort of the tasks
// themselves, without its buffer). Tasks number at most 2^22: each is a cell of an aligned grid
// of at least 16x16 px over a target of at most kMaxTargetSize (2^15) px a side.
constexpr int kTaskIndexBits = 24;
constexpr std::uint64_t kTaskIndexMask = (std::uint64_t{1} << kTaskIndexBits) - 1;

// One list of triangles a shading task walks, and the range whose screen mesh they index.
struct ListRef {
  std::size_t range;
  const CornerList* list;
};

// A rectangle to shade (a bin, or a sub-bin of a crowded one) and its lists, refs[first, end)
// of the call's ListRefs, in submission order.
struct ShadeTask {
  PixelRect rect;
  std::size_t first, end;
  std::size_t load = 0;  // task_load()
};

// How the shading phase's tasks are laid out: dealt(i) is the i-th task to deal.
struct ShadePlan {
  std::vector<ListRef> refs;
  std::vector<ShadeTask> tasks;
  std::vector<std::uint64_t> order;   // a task's load above its index, sorted (shading_plan.cpp)
  std::optional<BinLists> sub_lists;  // the chunks' lists, when some bin is crowded

  const ShadeTask& dealt(std::size_t i) const { return tasks[order[i] & kTaskIndexMask]; }
};

// The shading phase's tasks into `plan`: every bin, except that crowded bins (a mesh in the middle
// of the screen) are cut into sub-bins, so that no task holds far more than its share of the
// triangles and every thread has work to the end. Each tile lies in exactly one task's
// rectangle, and a task's lists are in submission order. The costliest tasks come first, so that
// the last to start are short ones. Crowded bins' triangles are binned again on the call's
// threads, and the culled triangles and errors found there counted into call.report.
void plan_shading(ShadePlan& plan, DrawCall& call, const BinGrid& grid, const BinLists& lists,
                  std::span<const ShadeBatch> range_batches);

}  // namespace edgewise::detail
