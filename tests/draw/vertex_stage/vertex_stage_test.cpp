// draw()'s vertex stage (kernels/draw/vertex_stage/vertex_stage.hpp, docs/design/vertex-stage.md
// "The vertex stage"):
// - every ISA's kernel gives the reference's screen mesh bit for bit: positions, depth, w,
//   attributes, indices and report, on random meshes that cross the near, far and guard-band
//   planes, put vertices near w = 0, hold NaN, infinite and huge coordinates and bad indices,
//   indexed and unindexed, of every length around the lane counts;
// - the screen triangles, in order, are those of clipping each mesh triangle alone with
//   clip_triangle() and mapping its vertices with to_screen(), snapped to 1/256 px: what draw()
//   drew before its vertex stage was vectorized, independently of how vertices are stored.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "draw/bitwise_same.hpp"
#include "edgewise/camera.hpp"
#include "edgewise/draw.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "draw/vertex_stage/clip.hpp"
#include "core/kernel_table.hpp"
#include "draw/vertex_stage/vertex_stage.hpp"

namespace edgewise::test::vertex_stage {
namespace {

// A mesh and how the stage sees it.
struct Case {
  std::vector<Vec3> positions;
  std::vector<Vec4> colors;
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
  std::vector<std::uint32_t> indices;
  Mat4 transform = identity();
  Viewport viewport{64, 48};
  bool diffuse = false;
  bool textured = false;

  detail::VertexStageCall call() const {
    const std::size_t corners = indices.empty() ? positions.size() : indices.size();
    return {{positions, colors, normals, indices, uvs},
            transform,
            viewport,
            guard_band_planes(viewport),
            diffuse,
            textured,
            corners / 3};
  }
};

float special_value(Random& random) {
  switch (random.integer(0, 7)) {
    case 0:
      return std::numeric_limits<float>::quiet_NaN();
    case 1:
      return random.chance(0.5) ? std::numeric_limits<float>::infinity()
                                : -std::numeric_limits<float>::infinity();
    case 2:
      return static_cast<float>(random.sign() * random.log_uniform(1e18, 1e30));
    case 3:
      return static_cast<float>(random.sign()) * kMaxClipCoordinate;  // the largest accepted
    case 4:
      return static_cast<float>(random.sign()) * std::nextafter(kMaxClipCoordinate, INFINITY);
    case 5:
      return -0.0f;
    case 6:
      return static_cast<float>(random.sign() * 1e-40);  // subnormal
    default:
      return 0.0f;
  }
}

// A scene around the view: mostly visible, some vertices beyond the near and far planes, the
// sides and the guard band (kGuardBand is 32768 px, about 1000 viewports of 64 px), behind the
// eye and near w = 0, and a few special values.
Case random_case(Random& random, std::size_t vertex_count) {
  Case c;
  c.viewport =
      random.chance(0.2)
          ? Viewport{kMaxTargetSize, static_cast<std::int32_t>(random.integer(1, kMaxTargetSize))}
          : Viewport{static_cast<std::int32_t>(random.integer(1, 300)),
                     static_cast<std::int32_t>(random.integer(1, 300))};
  const int camera = static_cast<int>(random.integer(0, 3));
  if (camera == 0) {
    c.transform = perspective(1.0f, 1.3f, 0.5f, 50.0f) * look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
  } else if (camera == 1) {
    c.transform = orthographic(-2, 2, -1.5f, 1.5f, 0.5f, 10.0f);
  } else if (camera == 2) {
    for (auto& row : c.transform.m) {
      for (float& v : row)
        v = static_cast<float>(random.uniform(-2.0, 2.0));
    }
  }  // else identity: the positions are clip space with w = 1
  const double spread = random.chance(0.3) ? 1.0 : random.log_uniform(1.0, 1e4);
  const bool all_inside = random.chance(0.3);
  for (std::size_t i = 0; i < vertex_count; ++i) {
    Vec3 p;
    if (all_inside) {  // in view, except for the random matrix's
      const double z = camera == 0   ? random.uniform(-4.0, 3.5)
                       : camera == 1 ? random.uniform(-9.0, -0.6)
                                     : random.uniform(0.05, 0.95);
      p = {static_cast<float>(random.uniform(-0.5, 0.5)),
           static_cast<float>(random.uniform(-0.5, 0.5)), static_cast<float>(z)};
    } else {
      p = {static_cast<float>(random.uniform(-spread, spread)),
           static_cast<float>(random.uniform(-spread, spread)),
           static_cast<float>(random.uniform(-12.0, 6.0))};
      if (random.chance(0.05)) p.z = static_cast<float>(5.0 + random.uniform(-1e-6, 1e-6));
    }
    if (random.chance(0.03)) {
      float* field[3] = {&p.x, &p.y, &p.z};
      *field[random.integer(0, 2)] = special_value(random);
    }
    c.positions.push_back(p);
  }
  if (random.chance(0.7)) {
    for (std::size_t i = 0; i < vertex_count; ++i) {
      c.colors.push_back({static_cast<float>(random.uniform()),
                          static_cast<float>(random.uniform()),
                          static_cast<float>(random.uniform()), 1.0f});
    }
  }
  c.diffuse = random.chance(0.4);
  if (c.diffuse) {
    for (std::size_t i = 0; i < vertex_count; ++i) {
      c.normals.push_back({static_cast<float>(random.uniform(-1, 1)),
                           static_cast<float>(random.uniform(-1, 1)), 1.0f});
    }
  }
  c.textured = random.chance(0.4);
  if (c.textured) {
    for (std::size_t i = 0; i < vertex_count; ++i)
      c.uvs.push_back({static_cast<float>(random.uniform()), static_cast<float>(random.uniform())});
  }
  if (random.chance(0.5)) {
    const std::size_t triangles = static_cast<std::size_t>(random.integer(0, 80));
    const double bad = random.chance(0.3) ? 0.02 : 0.0;
    for (std::size_t k = 0; k < 3 * triangles; ++k) {
      std::uint32_t index =
          vertex_count == 0 ? 0 : static_cast<std::uint32_t>(random.integer(0, vertex_count - 1));
      if (vertex_count == 0 || random.chance(bad)) {
        const std::uint32_t bad_indices[] = {static_cast<std::uint32_t>(vertex_count), 0x7fffffffu,
                                             0x80000000u, UINT32_MAX};
        index = bad_indices[random.integer(0, 3)];
      }
      c.indices.push_back(index);
    }
  } else {
    c.positions.resize(c.positions.size() / 3 * 3);
    if (!c.colors.empty()) c.colors.resize(c.positions.size());
    if (c.diffuse) c.normals.resize(c.positions.size());
    if (c.textured) c.uvs.resize(c.positions.size());
  }
  return c;
}

// Vertex counts around the lane counts (4 and 8) and their multiples, and some longer meshes.
std::size_t random_vertex_count(Random& random) {
  return random.chance(0.8) ? static_cast<std::size_t>(random.integer(0, 40))
                            : static_cast<std::size_t>(random.integer(41, 700));
}

template <class Array>
std::string first_difference(const Array& a, const Array& b, const char* name) {
  if (a.size() != b.size()) {
    return std::string(name) + ": " + std::to_string(a.size()) + " against " +
           std::to_string(b.size()) + " values";
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same(a[i], b[i])) return std::string(name) + "[" + std::to_string(i) + "] differs";
  }
  return {};
}

std::string first_difference(const detail::GrowableArray<std::uint32_t>& a,
                             const detail::GrowableArray<std::uint32_t>& b) {
  if (a.size() != b.size()) {
    return "indices: " + std::to_string(a.size()) + " against " + std::to_string(b.size());
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != b[i]) return "indices[" + std::to_string(i) + "] differs";
  }
  return {};
}

std::string compare_reports(const DrawReport& a, const DrawReport& b) {
  if (a.clipped != b.clipped || a.clip_triangles != b.clip_triangles || a.outside != b.outside ||
      a.culled != b.culled || a.errors != b.errors) {
    return "the reports differ";
  }
  return {};
}

struct StageResult {
  detail::ScreenMesh screen;
  DrawReport report;
};

StageResult run_stage(Isa isa, const Case& c) {
  StageResult result;
  detail::run_vertex_stage(detail::kernel_table(isa), c.call(), result.screen, result.report);
  return result;
}

// The first difference between two results of case `c`'s stage (its screen mesh, bit for bit,
// and its counts), or "" when there is none.
std::string first_difference(const Case& c, const StageResult& actual,
                             const StageResult& expected) {
  const detail::ScreenMesh& a = actual.screen;
  const detail::ScreenMesh& e = expected.screen;
  for (std::string difference :
       {first_difference(a.positions, e.positions, "positions"),
        first_difference(a.depth, e.depth, "depth"), first_difference(a.clip_w, e.clip_w, "clip_w"),
        first_difference(a.colors, e.colors, "colors"),
        c.diffuse ? first_difference(a.normals, e.normals, "normals") : std::string(),
        c.textured ? first_difference(a.uvs, e.uvs, "uvs") : std::string(),
        first_difference(a.indices, e.indices), compare_reports(actual.report, expected.report)}) {
    if (!difference.empty()) return difference;
  }
  return {};
}

using VertexStage = IsaTest;

TEST_P(VertexStage, EqualsTheReferenceBitForBit) {
  Random random(20240611);
  std::size_t clipped = 0, outside = 0, errors = 0, drawn = 0;
  for (int round = 0; round < 600; ++round) {
    const Case c = random_case(random, random_vertex_count(random));
    const StageResult expected = run_stage(Isa::reference, c);
    const StageResult actual = run_stage(isa(), c);
    ASSERT_EQ(first_difference(c, actual, expected), "")
        << "round " << round << ", " << c.positions.size() << " vertices, " << c.indices.size()
        << " indices";
    const detail::ScreenMesh& e = expected.screen;
    clipped += expected.report.clipped;
    outside += expected.report.outside;
    errors += expected.report.errors;
    drawn += e.indices.size() / 3;
  }
  // The random cases reach every outcome.
  EXPECT_GT(clipped, 100u);
  EXPECT_GT(outside, 100u);
  EXPECT_GT(errors, 50u);
  EXPECT_GT(drawn, 1000u);
}

// Cut points of [0, count) into `pieces` ranges at random places (some ranges empty).
std::vector<std::size_t> random_cuts(Random& random, std::size_t count, std::size_t pieces) {
  std::vector<std::size_t> cuts = {0, count};
  for (std::size_t i = 1; i < pieces; ++i)
    cuts.push_back(static_cast<std::size_t>(random.integer(0, count)));
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

// The stage as draw_indexed_in_ranges() runs it: vertices in ranges, then triangles in ranges,
// each range's clipped vertices in a screen mesh of its own, numbered on from the mesh's; joined
// here in range order as that function joins them.
StageResult run_stage_in_ranges(Isa isa, const Case& c, Random& random) {
  const detail::KernelTable& kernels = detail::kernel_table(isa);
  const detail::VertexStageCall call = c.call();
  const std::size_t vertices = c.positions.size();
  StageResult result;
  detail::ScreenMesh& screen = result.screen;
  detail::start_screen_mesh(call, screen);
  detail::GrowableArray<std::int32_t> codes(vertices);
  const std::vector<std::size_t> vertex_cuts =
      random_cuts(random, vertices, static_cast<std::size_t>(random.integer(1, 5)));
  for (std::size_t r = 0; r + 1 < vertex_cuts.size(); ++r)
    detail::map_vertex_range(kernels, call, vertex_cuts[r], vertex_cuts[r + 1], screen,
                             codes.data());
  const std::vector<std::size_t> cuts =
      random_cuts(random, call.triangles, static_cast<std::size_t>(random.integer(1, 5)));
  std::vector<detail::ScreenMesh> parts(cuts.size() - 1);
  for (std::size_t r = 0; r < parts.size(); ++r) {
    parts[r].first_vertex_index = vertices;
    kernels.assemble_triangles(call, codes.data(), cuts[r], cuts[r + 1], parts[r], result.report);
  }
  for (const detail::ScreenMesh& part : parts) {
    const auto shift = static_cast<std::uint32_t>(screen.positions.size() - vertices);
    for (std::size_t i = 0; i < part.indices.size(); ++i)
      screen.indices.push_back(part.indices[i] + (part.indices[i] >= vertices ? shift : 0));
    for (std::size_t i = 0; i < part.positions.size(); ++i) {
      screen.positions.push_back(part.positions[i]);
      screen.depth.push_back(part.depth[i]);
      screen.clip_w.push_back(part.clip_w[i]);
      screen.colors.push_back(part.colors[i]);
      if (c.diffuse) screen.normals.push_back(part.normals[i]);
      if (c.textured) screen.uvs.push_back(part.uvs[i]);
    }
  }
  return result;
}

// Ranges of vertices and of triangles cut anywhere (between an ISA's blocks of lanes too) give
// the whole stage's screen mesh bit for bit, and its counts.
TEST_P(VertexStage, RangesAssembledApartJoinToTheWholeStage) {
  Random random(20261129);
  std::size_t clipped = 0;
  for (int round = 0; round < 300; ++round) {
    const Case c = random_case(random, random_vertex_count(random));
    const StageResult whole = run_stage(isa(), c);
    const StageResult joined = run_stage_in_ranges(isa(), c, random);
    ASSERT_EQ(first_difference(c, joined, whole), "")
        << "round " << round << ", " << c.positions.size() << " vertices, " << c.indices.size()
        << " indices";
    clipped += whole.report.clipped;
  }
  EXPECT_GT(clipped, 50u);  // the clipped vertices' numbering is exercised
}

TEST_P(VertexStage, EmptyMeshGivesAnEmptyScreenMesh) {
  const Case c;
  const StageResult result = run_stage(isa(), c);
  EXPECT_EQ(result.screen.positions.size(), 0u);
  EXPECT_EQ(result.screen.indices.size(), 0u);
  EXPECT_EQ(result.report.errors + result.report.outside + result.report.clipped, 0u);
}

// One screen vertex, resolved through the indices.
struct Corner {
  Vec2 position;
  float depth, w;
  Vec4 color;
  Vec3 normal;
  Vec2 uv;
};

bool same_corner(const Corner& a, const Corner& b) {
  return same(a.position, b.position) && same(a.depth, b.depth) && same(a.w, b.w) &&
         same(a.color, b.color) && same(a.normal, b.normal) && same(a.uv, b.uv);
}

float snapped(float v) {
  return static_cast<float>(std::nearbyint(static_cast<double>(v) * 256.0) / 256.0);
}

// The triangles of each mesh triangle clipped alone, their vertices mapped one by one, and the
// report counted from clip_triangle()'s statuses.
std::vector<Corner> triangle_by_triangle(const Case& c, DrawReport& report) {
  const GuardBandPlanes planes = guard_band_planes(c.viewport);
  const std::size_t corners = c.indices.empty() ? c.positions.size() : c.indices.size();
  std::vector<Corner> out;
  for (std::size_t t = 0; t < corners / 3; ++t) {
    std::uint32_t v[3];
    bool in_range = true;
    for (int i = 0; i < 3; ++i) {
      v[i] = c.indices.empty() ? static_cast<std::uint32_t>(3 * t + i) : c.indices[3 * t + i];
      in_range = in_range && v[i] < c.positions.size();
    }
    if (!in_range) {
      ++report.errors;
      continue;
    }
    Vec4 clip[3], color[3];
    Vec3 normal[3];
    Vec2 uv[3];
    for (int i = 0; i < 3; ++i) {
      clip[i] = transform(c.transform, c.positions[v[i]]);
      color[i] = c.colors.empty() ? Vec4{1, 1, 1, 1} : c.colors[v[i]];
      normal[i] = c.diffuse ? c.normals[v[i]] : Vec3{0, 0, 0};
      uv[i] = c.textured ? c.uvs[v[i]] : Vec2{0, 0};
    }
    const ClippedPolygon polygon = clip_triangle(clip[0], clip[1], clip[2], planes);
    std::vector<Corner> fan;
    const auto corner = [&](const Vec4& p, const Vec4& col, const Vec3& n, const Vec2& u) {
      const ScreenVertex s = to_screen(p, c.viewport);
      fan.push_back({{snapped(s.x), snapped(s.y)}, s.z, p.w, col, n, u});
    };
    switch (polygon.status) {
      case ClipStatus::inside:
        for (int i = 0; i < 3; ++i)
          corner(clip[i], color[i], normal[i], uv[i]);
        break;
      case ClipStatus::clipped:
        ++report.clipped;
        report.clip_triangles += static_cast<std::uint64_t>(polygon.triangle_count());
        for (int k = 0; k < polygon.count; ++k) {
          const ClipVertex& p = polygon.vertices[k];
          const auto blend = [&p](float a, float b, float d) {
            return p.b0 * a + p.b1 * b + p.b2 * d;
          };
          corner(
              p.position,
              {blend(color[0].x, color[1].x, color[2].x), blend(color[0].y, color[1].y, color[2].y),
               blend(color[0].z, color[1].z, color[2].z),
               blend(color[0].w, color[1].w, color[2].w)},
              {blend(normal[0].x, normal[1].x, normal[2].x),
               blend(normal[0].y, normal[1].y, normal[2].y),
               blend(normal[0].z, normal[1].z, normal[2].z)},
              {blend(uv[0].x, uv[1].x, uv[2].x), blend(uv[0].y, uv[1].y, uv[2].y)});
        }
        break;
      case ClipStatus::outside:
        ++report.outside;
        break;
      case ClipStatus::culled_degenerate:
        ++report.culled;
        break;
      case ClipStatus::error_non_finite:
      case ClipStatus::error_out_of_range:
        ++report.errors;
        break;
    }
    for (std::size_t k = 0; k + 2 < fan.size(); ++k) {
      for (std::size_t i : {std::size_t{0}, k + 1, k + 2})
        out.push_back(fan[i]);
    }
  }
  return out;
}

TEST_P(VertexStage, DrawsWhatClippingEachTriangleAloneDraws) {
  Random random(77);
  for (int round = 0; round < 300; ++round) {
    const Case c = random_case(random, random_vertex_count(random));
    DrawReport expected_report;
    const std::vector<Corner> expected = triangle_by_triangle(c, expected_report);
    const StageResult actual = run_stage(isa(), c);
    const detail::ScreenMesh& s = actual.screen;
    ASSERT_EQ(s.indices.size(), expected.size()) << "round " << round;
    ASSERT_EQ(compare_reports(actual.report, expected_report), "") << "round " << round;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const std::uint32_t v = s.indices[k];
      ASSERT_LT(v, s.positions.size()) << "round " << round;
      const Corner corner{s.positions[v],
                          s.depth[v],
                          s.clip_w[v],
                          s.colors[v],
                          c.diffuse ? s.normals[v] : Vec3{0, 0, 0},
                          c.textured ? s.uvs[v] : Vec2{0, 0}};
      ASSERT_TRUE(same_corner(corner, expected[k])) << "round " << round << ", corner " << k;
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(VertexStage, every_isa());

}  // namespace
}  // namespace edgewise::test::vertex_stage
