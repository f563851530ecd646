// draw() on several threads (docs/design/threads.md): for 1, 2, 3 and 8 threads, on every ISA,
// the framebuffer (colour and depth, bit for bit) and every count of the report are those of one
// thread, on scenes with overlapping triangles, equal depths, clipping, culling, a scissor,
// hierarchical depth and textures; a caller's executor gives the same image; EDGEWISE_THREADS.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "edgewise/edgewise.hpp"
#include "isa_params.hpp"
#include "random.hpp"

namespace edgewise::test::draw_threads {
namespace {

constexpr std::int32_t kWidth = 331, kHeight = 203;  // bins of several sizes, partial tiles
constexpr float kFovy = 1.0f, kNearPlane = 0.5f, kFarPlane = 40.0f;
constexpr std::size_t kThreadCounts[] = {2, 3, 8};

struct ThreadScene {
  std::vector<Vec3> positions;  // three per triangle
  std::vector<Vec4> colors;
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
};

Vec3 jitter(Random& random, const Vec3& centre, double size) {
  return {static_cast<float>(centre.x + random.uniform(-size, size)),
          static_cast<float>(centre.y + random.uniform(-size, size)),
          static_cast<float>(centre.z + random.uniform(-0.3 * size, 0.3 * size))};
}

// Random triangles in front of a perspective camera, of sizes from a pixel to the whole view,
// many partly outside it; some cross the near plane, some reach far past the guard band (both
// clipped), some have zero area, and some repeat an earlier triangle (equal depths) in another
// colour. More than kMinTrianglesPerRange (kernels/coverage/triangle_binning.hpp) twice over, so
// that several threads bin several ranges. Centres lie within `spread` times the half-view on each
// axis, sizes up to `largest` times the half-height.
ThreadScene thread_scene(std::uint64_t seed, int triangles, double spread = 1.2,
                         double largest = 0.5) {
  Random random(seed);
  ThreadScene scene;
  const double aspect = static_cast<double>(kWidth) / kHeight;
  const auto add = [&](const Vec3(&v)[3]) {
    for (const Vec3& p : v) {
      scene.positions.push_back(p);
      scene.colors.push_back({static_cast<float>(random.uniform()),
                              static_cast<float>(random.uniform()),
                              static_cast<float>(random.uniform()), 1.0f});
      scene.normals.push_back({static_cast<float>(random.uniform(-0.5, 0.5)),
                               static_cast<float>(random.uniform(-0.5, 0.5)), 1.0f});
      scene.uvs.push_back({static_cast<float>(random.uniform(-1.0, 2.0)),
                           static_cast<float>(random.uniform(-1.0, 2.0))});
    }
  };
  for (int t = 0; t < triangles; ++t) {
    if (t > 0 && random.chance(0.1)) {  // an earlier triangle again: equal depths
      const std::size_t earlier = 3 * static_cast<std::size_t>(random.integer(0, t - 1));
      const Vec3 v[3] = {scene.positions[earlier], scene.positions[earlier + 1],
                         scene.positions[earlier + 2]};
      add(v);
      continue;
    }
    const double depth = random.uniform(1.0, 30.0);
    const double half_height = depth * std::tan(0.5 * kFovy);
    const Vec3 centre{static_cast<float>(random.uniform(-spread, spread) * half_height * aspect),
                      static_cast<float>(random.uniform(-spread, spread) * half_height),
                      static_cast<float>(-depth)};
    const double size = half_height * random.log_uniform(0.004, largest);
    Vec3 v[3] = {jitter(random, centre, size), jitter(random, centre, size),
                 jitter(random, centre, size)};
    if (random.chance(0.03)) v[2].z = 1.0f;  // behind the camera: the near plane cuts it
    if (random.chance(0.02)) {               // far past the guard band: its planes cut it
      v[1].x = static_cast<float>(centre.x + 4000.0 * half_height);
      v[2].y = static_cast<float>(centre.y - 3000.0 * half_height);
    }
    if (random.chance(0.02)) v[2] = v[1];  // zero area
    add(v);
  }
  return scene;
}

DrawMesh mesh_of(const ThreadScene& scene, const std::vector<std::uint32_t>& indices = {}) {
  return {scene.positions, scene.colors, scene.normals, indices, scene.uvs};
}

DrawOptions base_options(Isa isa) {
  DrawOptions options;
  options.transform =
      perspective(kFovy, static_cast<float>(kWidth) / kHeight, kNearPlane, kFarPlane);
  options.isa = isa;
  return options;
}

struct Frame {
  std::vector<DrawReport> reports;  // one per draw
  std::vector<std::uint32_t> color;
  std::vector<float> depth;
};

// Every draw of `draws` into one cleared framebuffer with `samples` per pixel, with `threads`
// (and `executor`) set; the frame holds every sample's image, sample 0's first.
Frame render(const std::vector<std::pair<DrawMesh, DrawOptions>>& draws, std::size_t threads,
             const TaskExecutor& executor = {}, int samples = 1) {
  Framebuffer target(kWidth, kHeight, samples);
  target.clear({0.1f, 0.2f, 0.3f, 1.0f}, 1.0f);
  Frame frame;
  for (auto [mesh, options] : draws) {
    options.threads = threads;
    options.executor = executor;
    frame.reports.push_back(draw(target, mesh, options));
  }
  const std::size_t pixels = static_cast<std::size_t>(kWidth) * kHeight;
  std::vector<std::uint8_t> rgba(pixels * 4);
  std::vector<float> depth(pixels);
  for (int k = 0; k < samples; ++k) {
    target.read_rgba8(rgba, k);
    for (std::size_t i = 0; i < pixels; ++i) {
      frame.color.push_back(rgba[4 * i] | rgba[4 * i + 1] << 8 | rgba[4 * i + 2] << 16 |
                            static_cast<std::uint32_t>(rgba[4 * i + 3]) << 24);
    }
    target.read_depth(depth, k);
    frame.depth.insert(frame.depth.end(), depth.begin(), depth.end());
  }
  return frame;
}

// Depths compared as bits: NaN and -0 too.
std::vector<std::uint32_t> depth_bits(const std::vector<float>& depth) {
  std::vector<std::uint32_t> bits(depth.size());
  std::memcpy(bits.data(), depth.data(), depth.size() * sizeof(float));
  return bits;
}

void expect_same_report(const DrawReport& one, const DrawReport& many, const std::string& what) {
  EXPECT_EQ(one.triangles, many.triangles) << what;
  EXPECT_EQ(one.clipped, many.clipped) << what;
  EXPECT_EQ(one.clip_triangles, many.clip_triangles) << what;
  EXPECT_EQ(one.outside, many.outside) << what;
  EXPECT_EQ(one.culled, many.culled) << what;
  EXPECT_EQ(one.errors, many.errors) << what;
  EXPECT_EQ(one.rasterized, many.rasterized) << what;
  EXPECT_EQ(one.fragments, many.fragments) << what;
  EXPECT_EQ(one.fragments_passed, many.fragments_passed) << what;
  EXPECT_EQ(one.statistics.tiles_skipped, many.statistics.tiles_skipped) << what;
  EXPECT_EQ(one.isa, many.isa) << what;
}

void expect_same_frame(const Frame& one, const Frame& many, const std::string& what) {
  ASSERT_EQ(one.reports.size(), many.reports.size());
  for (std::size_t d = 0; d < one.reports.size(); ++d)
    expect_same_report(one.reports[d], many.reports[d], what + ", draw " + std::to_string(d));
  std::size_t colour_differences = 0, depth_differences = 0;
  const std::vector<std::uint32_t> one_depth = depth_bits(one.depth);
  const std::vector<std::uint32_t> many_depth = depth_bits(many.depth);
  for (std::size_t i = 0; i < one.color.size(); ++i) {
    colour_differences += one.color[i] != many.color[i];
    depth_differences += one_depth[i] != many_depth[i];
  }
  EXPECT_EQ(colour_differences, 0u) << what << ": pixels whose colour differs";
  EXPECT_EQ(depth_differences, 0u) << what << ": pixels whose depth differs";
}

// The draws with 1 thread, then with each of kThreadCounts: the same frame each time.
void expect_same_for_every_thread_count(
    const std::vector<std::pair<DrawMesh, DrawOptions>>& draws) {
  const Frame one = render(draws, 1);
  for (std::size_t threads : kThreadCounts)
    expect_same_frame(one, render(draws, threads), std::to_string(threads) + " threads");
}

using DrawThreads = IsaTest;

const ThreadScene& shared_scene() {
  static const ThreadScene scene = thread_scene(11, 5000);
  return scene;
}

TEST_P(DrawThreads, OverlappingClippedTrianglesDrawTheSameImage) {
  const ThreadScene& scene = shared_scene();
  const Frame one = render({{mesh_of(scene), base_options(isa())}}, 1);
  // The scene exercises what it should.
  EXPECT_GT(one.reports[0].clipped, 0u);
  EXPECT_GT(one.reports[0].culled, 0u);
  EXPECT_GT(one.reports[0].fragments_passed, 0u);
  EXPECT_LT(one.reports[0].fragments_passed, one.reports[0].fragments);
  for (std::size_t threads : kThreadCounts) {
    expect_same_frame(one, render({{mesh_of(scene), base_options(isa())}}, threads),
                      std::to_string(threads) + " threads");
  }
}

// With indices, the vertex stage runs in ranges of vertices, then of triangles.
TEST_P(DrawThreads, IndexedMeshDrawsTheSameImage) {
  const ThreadScene& scene = shared_scene();
  std::vector<std::uint32_t> indices(scene.positions.size());
  for (std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = static_cast<std::uint32_t>(indices.size() - 1 - i);  // every triangle reversed
  DrawOptions options = base_options(isa());
  options.interpolation = InterpolationMethod::scanline;
  expect_same_for_every_thread_count({{mesh_of(scene, indices), options}});
}

// A ground grid just below the eye whose triangles share their vertices, in a random order, so
// that every range of triangles holds some that the near plane clips and shares vertices with
// the others: coloured, lit and textured, so that every attribute of the clipped vertices
// follows the mesh's.
TEST_P(DrawThreads, IndexedGridClippedInEveryRangeDrawsTheSameImage) {
  constexpr int kSide = 60;  // vertices a side: 6,962 triangles, several ranges
  ThreadScene grid;
  Random random(29);
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      grid.positions.push_back(
          {-1.0f + 2.0f * i / (kSide - 1), -0.2f, 1.0f - 11.0f * j / (kSide - 1)});
      grid.colors.push_back(
          {static_cast<float>(random.uniform()), static_cast<float>(random.uniform()), 0.5f, 1.0f});
      grid.normals.push_back({static_cast<float>(random.uniform(-0.3, 0.3)), 1.0f, 0.0f});
      grid.uvs.push_back({0.5f * i, 0.5f * j});
    }
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (int i = 0; i + 1 < kSide; ++i) {
    for (int j = 0; j + 1 < kSide; ++j) {
      const auto v = [](int x, int z) { return static_cast<std::uint32_t>(x * kSide + z); };
      triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  }
  for (std::size_t k = triangles.size(); k > 1; --k)  // Fisher-Yates
    std::swap(triangles[k - 1], triangles[static_cast<std::size_t>(random.integer(0, k - 1))]);
  std::vector<std::uint32_t> indices;
  for (const auto& triangle : triangles)
    indices.insert(indices.end(), triangle.begin(), triangle.end());
  std::vector<std::uint8_t> texels(16 * 16 * 4);
  for (std::uint8_t& t : texels)
    t = static_cast<std::uint8_t>(random.integer(0, 255));
  const Texture texture = Texture::from_rgba8(16, 16, texels, ColorEncoding::linear);
  DrawOptions options = base_options(isa());
  options.shading = Shading::diffuse;
  options.texture = DrawTexture{&texture, {}, TextureDerivatives::quad};
  options.texture->sampler.filter = TextureFilter::bilinear;
  const std::vector<std::pair<DrawMesh, DrawOptions>> draws = {{mesh_of(grid, indices), options}};
  const Frame one = render(draws, 1);
  EXPECT_GT(one.reports[0].clipped, 20u) << "the near plane cuts the grid in view";
  EXPECT_GT(one.reports[0].fragments_passed, 0u);
  for (std::size_t threads : kThreadCounts)
    expect_same_frame(one, render(draws, threads), std::to_string(threads) + " threads");
}

TEST_P(DrawThreads, EqualDepthsAndCullingDrawTheSameImage) {
  const ThreadScene& scene = shared_scene();
  for (DepthTest test : {DepthTest::less_equal, DepthTest::always}) {
    DrawOptions options = base_options(isa());
    options.depth_test = test;
    options.cull = CullMode::clockwise;
    options.shading = Shading::flat;
    expect_same_for_every_thread_count({{mesh_of(scene), options}});
  }
}

// Two draws into one target: the second meets the first's depth bounds (hierarchical depth), in
// a scissor that cuts tiles and bins.
TEST_P(DrawThreads, ScissorAndHierarchicalDepthDrawTheSameImage) {
  const ThreadScene& scene = shared_scene();
  static const ThreadScene second = thread_scene(12, 4500);
  DrawOptions first_options = base_options(isa());
  DrawOptions second_options = base_options(isa());
  second_options.scissor = PixelRect{13, 7, 301, 190};
  second_options.depth_write = false;
  second_options.shading = Shading::diffuse;
  const std::vector<std::pair<DrawMesh, DrawOptions>> draws = {{mesh_of(scene), first_options},
                                                               {mesh_of(second), second_options}};
  const Frame one = render(draws, 1);
  if (isa() != Isa::reference) {
    EXPECT_GT(one.reports[1].statistics.tiles_skipped, 0u);
  }
  for (std::size_t threads : kThreadCounts)
    expect_same_frame(one, render(draws, threads), std::to_string(threads) + " threads");
}

TEST_P(DrawThreads, TexturedDrawsTheSameImage) {
  Random random(3);
  std::vector<std::uint8_t> texels(32 * 32 * 4);
  for (std::uint8_t& v : texels)
    v = static_cast<std::uint8_t>(random.integer(0, 255));
  const Texture texture = Texture::from_rgba8(32, 32, texels, ColorEncoding::srgb);
  DrawOptions options = base_options(isa());
  options.texture = DrawTexture{&texture, {}, TextureDerivatives::quad};
  options.texture->sampler.filter = TextureFilter::trilinear;
  // The reference samples slowly: fewer triangles.
  static const ThreadScene scene = thread_scene(13, 4200);
  expect_same_for_every_thread_count({{mesh_of(scene), options}});
}

// Multisampled targets: every sample of every pixel, as with one thread. Binning widens each
// triangle's box by the patterns' reach, so a sample beyond its pixel centre's bin is drawn by
// the bin that holds the pixel.
TEST_P(DrawThreads, MultisampledDrawsTheSameImage) {
  static const ThreadScene scene = thread_scene(17, 2100);
  for (int samples : {4, 16}) {
    const Frame one = render({{mesh_of(scene), base_options(isa())}}, 1, {}, samples);
    EXPECT_GT(one.reports[0].fragments_passed, 0u);
    EXPECT_LT(one.reports[0].fragments_passed, one.reports[0].fragments);  // overlaps hidden
    for (std::size_t threads : kThreadCounts) {
      expect_same_frame(
          one, render({{mesh_of(scene), base_options(isa())}}, threads, {}, samples),
          std::to_string(samples) + " samples, " + std::to_string(threads) + " threads");
    }
  }
}

// A crowded view: nearly every triangle within a bin or a few (a mesh in the middle of the
// screen), so that the bins that hold them are binned again into sub-bins for balance
// (kernels/draw/binned_draw.cpp, plan_shading()): a phase more, and the same image and counts,
// with culled and zero-area triangles among those the first binning leaves undecided.
TEST_P(DrawThreads, CrowdedViewCutIntoSubBinsDrawsTheSameImage) {
  // Within one 64x64 bin; within about six, which only 8 threads cut.
  static const ThreadScene narrow = thread_scene(19, 4400, 0.06, 0.04);
  static const ThreadScene wider = thread_scene(23, 4400, 0.3, 0.1);
  for (const ThreadScene* scene : {&narrow, &wider}) {
    DrawOptions options = base_options(isa());
    options.cull = CullMode::clockwise;
    options.shading = Shading::diffuse;
    const std::vector<std::pair<DrawMesh, DrawOptions>> draws = {{mesh_of(*scene), options}};
    const Frame one = render(draws, 1);
    EXPECT_GT(one.reports[0].culled, 0u);
    EXPECT_LT(one.reports[0].fragments_passed, one.reports[0].fragments);  // overlaps hidden
    for (std::size_t threads : kThreadCounts) {
      std::size_t runs = 0;
      const TaskExecutor builtin = builtin_executor(threads);
      const TaskExecutor counted = [&](std::size_t count,
                                       const std::function<void(std::size_t)>& task) {
        ++runs;
        builtin(count, task);
      };
      const std::string what = std::string(scene == &narrow ? "narrow" : "wider") + ", " +
                               std::to_string(threads) + " threads";
      expect_same_frame(one, render(draws, threads, counted), what);
      if (scene == &narrow || threads == 8) {
        EXPECT_EQ(runs, 3u) << what << ": binning, the crowded bins binned again, then the bins";
      }
    }
  }
}

// A caller's executor: here one that runs the tasks one after the other, last first.
TEST_P(DrawThreads, CallersExecutorDrawsTheSameImage) {
  const ThreadScene& scene = shared_scene();
  std::size_t runs = 0, tasks = 0;
  const TaskExecutor reversed = [&](std::size_t count,
                                    const std::function<void(std::size_t)>& task) {
    ++runs;
    tasks += count;
    for (std::size_t i = count; i-- > 0;)
      task(i);
  };
  const std::vector<std::pair<DrawMesh, DrawOptions>> draws = {
      {mesh_of(scene), base_options(isa())}};
  const Frame one = render(draws, 1, reversed);
  EXPECT_EQ(runs, 0u) << "one thread runs no tasks: it draws directly";
  for (std::size_t threads : kThreadCounts) {
    runs = 0;
    expect_same_frame(one, render(draws, threads, reversed),
                      std::to_string(threads) + " threads, reversed executor");
    EXPECT_GE(runs, 2u) << "binning, then the bins";
    EXPECT_LE(runs, 3u) << "binning, crowded bins binned again, then the bins";
  }
  // And one that runs them on threads of its own, all at once.
  const TaskExecutor spawning = [](std::size_t count,
                                   const std::function<void(std::size_t)>& task) {
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < count; ++i)
      threads.emplace_back(task, i);
    for (std::thread& thread : threads)
      thread.join();
  };
  expect_same_frame(one, render(draws, 4, spawning), "4 threads, one std::thread per task");
  // And the built-in executor, wrapped to count its runs: as without an executor.
  for (std::size_t threads : kThreadCounts) {
    runs = 0;
    const TaskExecutor builtin = builtin_executor(threads);
    const TaskExecutor counted = [&](std::size_t count,
                                     const std::function<void(std::size_t)>& task) {
      ++runs;
      builtin(count, task);
    };
    expect_same_frame(one, render(draws, threads, counted),
                      std::to_string(threads) + " threads, the built-in executor wrapped");
    EXPECT_GE(runs, 2u) << "binning, then the bins";
    EXPECT_LE(runs, 3u) << "binning, crowded bins binned again, then the bins";
  }
}

INSTANTIATE_TEST_SUITE_P(Isas, DrawThreads, ::testing::ValuesIn(every_isa()), isa_test_name);

// EDGEWISE_THREADS, set for the scope of one test.
class ThreadsVariable {
 public:
  explicit ThreadsVariable(const char* value) {
    if (const char* old = std::getenv("EDGEWISE_THREADS")) saved_ = old;
    setenv("EDGEWISE_THREADS", value, 1);
  }
  ~ThreadsVariable() {
    if (saved_) {
      setenv("EDGEWISE_THREADS", saved_->c_str(), 1);
    } else {
      unsetenv("EDGEWISE_THREADS");
    }
  }

 private:
  std::optional<std::string> saved_;
};

TEST(ThreadCount, EnvironmentVariableSetsTheDefault) {
  {
    const ThreadsVariable variable("3");
    EXPECT_EQ(default_thread_count(), 3u);
  }
  {
    const ThreadsVariable variable("1024");
    EXPECT_EQ(default_thread_count(), kMaxThreads);
  }
  std::size_t unset = 0;
  {
    const ThreadsVariable variable("");  // empty counts as unset
    unset = default_thread_count();
  }
  EXPECT_GE(unset, 1u);
}

TEST(ThreadCount, GarbageInTheEnvironmentVariableThrows) {
  for (const char* value :
       {"0", "-2", "+2", " 2", "2 ", "two", "2.5", "1025", "99999999999999999999"}) {
    const ThreadsVariable variable(value);
    EXPECT_THROW(default_thread_count(), std::invalid_argument) << "EDGEWISE_THREADS=" << value;
    // A call that takes the default reads it too; one with its own count does not.
    Framebuffer target(16, 16);
    const Vec3 positions[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    DrawMesh mesh;
    mesh.positions = positions;
    DrawOptions options;
    EXPECT_THROW(draw(target, mesh, options), std::invalid_argument) << value;
    options.threads = 2;
    EXPECT_NO_THROW(draw(target, mesh, options)) << value;
  }
}

TEST(ThreadCount, BuiltinExecutorRunsEveryTaskOnce) {
  for (std::size_t threads : {std::size_t{1}, std::size_t{2}, std::size_t{5}}) {
    std::vector<std::atomic<int>> runs(37);
    builtin_executor(threads)(runs.size(), [&](std::size_t i) { ++runs[i]; });
    for (std::size_t i = 0; i < runs.size(); ++i)
      EXPECT_EQ(runs[i].load(), 1) << "task " << i << " on " << threads << " threads";
  }
  EXPECT_THROW(builtin_executor(kMaxThreads + 1), std::invalid_argument);
}

TEST(ThreadCount, TooManyThreadsThrow) {
  Framebuffer target(16, 16);
  const Vec3 positions[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  DrawMesh mesh;
  mesh.positions = positions;
  DrawOptions options;
  options.threads = kMaxThreads + 1;
  EXPECT_THROW(draw(target, mesh, options), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::test::draw_threads
