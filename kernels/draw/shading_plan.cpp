// The shading phase's plan for a binned draw (shading_plan.hpp).
#include "shading_plan.hpp"

#include <algorithm>

namespace edgewise::detail {
namespace {

// The largest load a key holds: larger ones deal as if they were this (costliest first anyway).
constexpr std::uint64_t kLargestKeyLoad = (std::uint64_t{1} << (64 - kTaskIndexBits)) - 1;

// A crowded bin cut into sub-bins (`grid` over the bin's rectangle). Its triangles are binned
// again in pieces, its chunks [first_chunk, first_chunk + chunks), each into lists of its own:
// the lists of chunk c start at first_list + (c - first_chunk) * grid.count().
struct SplitBin {
  std::size_t bin;
  BinGrid grid;
  std::size_t first_chunk = 0, chunks = 0, first_list = 0;
};

// A piece of a crowded bin's triangles: triangles [first, last) of its list from `range`.
struct Chunk {
  std::size_t split, range, first, last;
};

// The triangles in each bin's lists, over all ranges (the ranges' recorded counts).
std::vector<std::size_t> bin_loads(const BinGrid& grid, const BinLists& lists, std::size_t ranges) {
  std::vector<std::size_t> loads(grid.count(), 0);
  for (std::size_t range = 0; range < ranges; ++range) {
    for (std::size_t bin = 0; bin < loads.size(); ++bin)
      loads[bin] += lists.triangles(range, bin);
  }
  return loads;
}

// A task's estimated cost in triangles: its `triangles`, and a triangle for every
// kPixelsPerTriangle px of its rectangle when it has any (the one-thread rates of 8-px and
// 200000-px triangles of the Shading/ benchmark, docs/design/threads.md, put a small triangle at
// about 500 to 700 px of a large one's pixels).
constexpr std::size_t kPixelsPerTriangle = 512;
std::size_t task_load(const PixelRect& rect, std::size_t triangles) {
  if (triangles == 0) return 0;
  const auto pixels =
      static_cast<std::size_t>(rect.x1 - rect.x0) * static_cast<std::size_t>(rect.y1 - rect.y0);
  return triangles + pixels / kPixelsPerTriangle;
}

// The sub-bins for a bin of `load` triangles when a task's share is `share`: its longer side
// halved (the width first) while a sub-bin would hold more than the share, down to sides of
// 2^kMinSplitBinShift px.
BinGrid split_grid(const BinGrid& grid, std::size_t bin, std::size_t load, std::size_t share) {
  int width_shift = grid.width_shift, height_shift = grid.height_shift;
  for (std::size_t parts = 1; load > share * parts; parts *= 2) {
    if (width_shift >= height_shift && width_shift > kMinSplitBinShift) {
      --width_shift;
    } else if (height_shift > kMinSplitBinShift) {
      --height_shift;
    } else {
      break;
    }
  }
  return BinGrid(grid.rect(bin), width_shift, height_shift);
}

// The crowded bins (over a thread's share of the triangles, so that no schedule could balance
// them, and at least kMinSplitTriangles), each with its sub-bins, and their chunks: both of
// about a task's share (kTasksPerThread to a thread).
std::vector<SplitBin> find_crowded_bins(const BinGrid& grid, const BinLists& lists,
                                        std::span<const std::size_t> loads, std::size_t ranges,
                                        std::size_t threads, std::vector<Chunk>& chunks) {
  std::vector<SplitBin> splits;
  if (threads < 2) return splits;  // one thread (a multisampled call) has nothing to balance
  std::size_t total = 0;
  for (std::size_t load : loads)
    total += load;
  const std::size_t share = std::max<std::size_t>(1, total / (threads * kTasksPerThread));
  const std::size_t chunk = std::max(share, kMinSplitTriangles);
  std::size_t sub_lists = 0;
  for (std::size_t bin = 0; bin < loads.size(); ++bin) {
    if (loads[bin] < kMinSplitTriangles || threads * loads[bin] <= total) continue;
    SplitBin split{bin, split_grid(grid, bin, loads[bin], share)};
    if (split.grid.count() < 2) continue;
    split.first_chunk = chunks.size();
    for (std::size_t range = 0; range < ranges; ++range) {
      const std::size_t triangles = lists.triangles(range, bin);
      for (std::size_t first = 0; first < triangles; first += chunk)
        chunks.push_back({splits.size(), range, first, std::min(triangles, first + chunk)});
    }
    split.chunks = chunks.size() - split.first_chunk;
    split.first_list = sub_lists;
    sub_lists += split.chunks * split.grid.count();
    splits.push_back(split);
  }
  return splits;
}

// Bins each chunk of the crowded bins again over its bin's sub-bins, one task per chunk, with
// bin_screen_triangles() as the first binning: a triangle still undecided goes to the one
// sub-bin it can reach or is decided here.
void split_crowded_bins(DrawCall& call, const BinLists& lists,
                        std::span<const ShadeBatch> range_batches, std::span<const SplitBin> splits,
                        std::span<const Chunk> chunks, BinLists& sub_lists) {
  std::vector<RasterReport> reports(chunks.size());
  call.workers.run(chunks.size(), [&](std::size_t c) {
    const Chunk& chunk = chunks[c];
    const SplitBin& split = splits[chunk.split];
    const CornerList& list = lists.list(chunk.range, split.bin);
    TriangleBatch batch = range_batches[chunk.range].coverage;
    batch.indices = list.data();
    batch.triangle_count = list.triangles();
    batch.clip = split.grid.clip;
    batch.statuses = nullptr;
    CornerList* out =
        sub_lists.lists_from(split.first_list + (c - split.first_chunk) * split.grid.count());
    for (std::size_t s = 0; s < split.grid.count(); ++s)
      out[s].clear();
    bin_screen_triangles(batch, chunk.first, chunk.last, split.grid, out, reports[c]);
  });
  // Only triangles the first binning left undecided can be decided as culled or errors here,
  // and each is in one bin: counted once, as a bin's kernel call counts them.
  DrawReport& report = call.report;
  for (const RasterReport& part : reports) {
    report.culled += part.culled;
    report.errors += part.errors;
    report.rasterized -= part.culled + part.errors;
  }
}

}  // namespace

void plan_shading(ShadePlan& plan, DrawCall& call, const BinGrid& grid, const BinLists& lists,
                  std::span<const ShadeBatch> range_batches) {
  const std::size_t ranges = range_batches.size();
  const std::vector<std::size_t> loads = bin_loads(grid, lists, ranges);
  std::vector<Chunk> chunks;
  const std::vector<SplitBin> splits =
      find_crowded_bins(grid, lists, loads, ranges, call.workers.threads, chunks);
  if (!splits.empty()) {
    const SplitBin& last = splits.back();
    plan.sub_lists.emplace(1, last.first_list + last.chunks * last.grid.count());
    split_crowded_bins(call, lists, range_batches, splits, chunks, *plan.sub_lists);
  }
  plan.tasks.reserve(grid.count());
  std::size_t next_split = 0;
  for (std::size_t bin = 0; bin < grid.count(); ++bin) {
    if (next_split < splits.size() && splits[next_split].bin == bin) {
      // A chunk's sub-lists were written by its task, on one core: read as they are.
      const SplitBin& split = splits[next_split++];
      const std::size_t count = split.grid.count();
      for (std::size_t s = 0; s < count; ++s) {
        ShadeTask task{split.grid.rect(s), plan.refs.size(), 0};
        std::size_t triangles = 0;
        for (std::size_t c = 0; c < split.chunks; ++c) {
          const CornerList& list = plan.sub_lists->list(0, split.first_list + c * count + s);
          if (list.empty()) continue;
          plan.refs.push_back({chunks[split.first_chunk + c].range, &list});
          triangles += list.triangles();
        }
        task.end = plan.refs.size();
        task.load = task_load(task.rect, triangles);
        plan.tasks.push_back(task);
      }
      continue;
    }
    ShadeTask task{grid.rect(bin), plan.refs.size(), 0};
    for (std::size_t range = 0; range < ranges; ++range) {
      if (lists.triangles(range, bin) != 0) plan.refs.push_back({range, &lists.list(range, bin)});
    }
    task.end = plan.refs.size();
    task.load = task_load(task.rect, loads[bin]);
    plan.tasks.push_back(task);
  }
  plan.order.resize(plan.tasks.size());
  for (std::size_t i = 0; i < plan.tasks.size(); ++i) {
    const std::uint64_t load = std::min<std::uint64_t>(plan.tasks[i].load, kLargestKeyLoad);
    plan.order[i] = (kLargestKeyLoad - load) << kTaskIndexBits | i;
  }
  std::sort(plan.order.begin(), plan.order.end());
}

}  // namespace edgewise::detail
