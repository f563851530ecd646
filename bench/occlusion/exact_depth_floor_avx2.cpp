// exact_depth_floor.hpp's kernel, compiled with AVX2 (and without FMA, as depth_plane.hpp's
// formula rounds every product). The operations follow the library's set-up where it must be
// matched bit for bit (triangle_setup-inl.hpp, plane_setup-inl.hpp, screen_mapping-inl.hpp); the
// benchmark compares the depths with draw_occluders()'s after its runs.
#include <immintrin.h>

#include <algorithm>
#include <cstdint>

#include "exact_depth_floor.hpp"

namespace edgewise::bench {
namespace {

constexpr int kLanes = 8;

// A group's triangles after set-up, lane by lane.
struct FloorGroup {
  alignas(32) std::int32_t x[3][kLanes], y[3][kLanes];  // snapped, 1/256 px, clockwise
  alignas(32) std::int32_t box[4][kLanes];              // pixels [x0, x1) x [y0, y1)
  alignas(32) float z0[kLanes], dzdx[kLanes], dzdy[kLanes];
};

// The view's (x, y) of lane values in NDC, snapped to 1/256 px (exact in int32 on screen).
__m256i snap_x(__m256 ndc) {
  const __m256 screen =
      _mm256_mul_ps(_mm256_add_ps(ndc, _mm256_set1_ps(1.0f)), _mm256_set1_ps(0.5f * kWidth));
  return _mm256_cvtps_epi32(_mm256_mul_ps(screen, _mm256_set1_ps(256.0f)));
}
__m256i snap_y(__m256 ndc) {
  const __m256 screen =
      _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(1.0f), ndc), _mm256_set1_ps(0.5f * kHeight));
  return _mm256_cvtps_epi32(_mm256_mul_ps(screen, _mm256_set1_ps(256.0f)));
}

__m256d lanes_as_double(__m256 v, int half) {
  return _mm256_cvtps_pd(half == 0 ? _mm256_castps256_ps128(v) : _mm256_extractf128_ps(v, 1));
}

// All bits set in the int32 lanes whose area (two halves of four doubles) compares to 0 as
// `predicate` says.
template <int predicate>
__m256i lanes_where(const __m256d (&area)[2]) {
  const int bits = _mm256_movemask_pd(_mm256_cmp_pd(area[0], _mm256_setzero_pd(), predicate)) |
                   _mm256_movemask_pd(_mm256_cmp_pd(area[1], _mm256_setzero_pd(), predicate)) << 4;
  const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  return _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(bits), lane_bit), lane_bit);
}

// Triangles [first, first + count) of `t` (count <= 8) set up in lanes; lanes past `count` get an
// empty box.
void set_up_group(const FillrateTriangles& t, std::size_t first, std::size_t count, FloorGroup& g) {
  alignas(32) float nx[3][kLanes] = {}, ny[3][kLanes] = {}, nz[3][kLanes] = {};
  for (std::size_t l = 0; l < count; ++l) {
    for (int i = 0; i < 3; ++i) {
      const Vec3& v = t.ndc[3 * (first + l) + i];
      nx[i][l] = v.x;
      ny[i][l] = v.y;
      nz[i][l] = std::clamp(v.z, 0.0f, 1.0f);  // z/w with w = 1
    }
  }
  __m256i x[3], y[3];
  __m256 z[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = snap_x(_mm256_load_ps(nx[i]));
    y[i] = snap_y(_mm256_load_ps(ny[i]));
    z[i] = _mm256_load_ps(nz[i]);
  }
  // The depth slopes in double from the snapped positions, as plane_setup-inl.hpp computes them
  // (the order of vertices 1 and 2 does not change them: both the numerators and the area change
  // sign).
  const __m256 inv256 = _mm256_set1_ps(1.0f / 256.0f);
  __m256 px[3], py[3];
  for (int i = 0; i < 3; ++i) {
    px[i] = _mm256_mul_ps(_mm256_cvtepi32_ps(x[i]), inv256);
    py[i] = _mm256_mul_ps(_mm256_cvtepi32_ps(y[i]), inv256);
  }
  __m256d area[2];
  for (int h = 0; h < 2; ++h) {
    const __m256d x0 = lanes_as_double(px[0], h), y0 = lanes_as_double(py[0], h);
    const __m256d x1 = _mm256_sub_pd(lanes_as_double(px[1], h), x0);
    const __m256d y1 = _mm256_sub_pd(lanes_as_double(py[1], h), y0);
    const __m256d x2 = _mm256_sub_pd(lanes_as_double(px[2], h), x0);
    const __m256d y2 = _mm256_sub_pd(lanes_as_double(py[2], h), y0);
    const __m256d z0 = lanes_as_double(z[0], h);
    const __m256d z1 = _mm256_sub_pd(lanes_as_double(z[1], h), z0);
    const __m256d z2 = _mm256_sub_pd(lanes_as_double(z[2], h), z0);
    area[h] = _mm256_sub_pd(_mm256_mul_pd(x1, y2), _mm256_mul_pd(y1, x2));
    const __m256d dx =
        _mm256_div_pd(_mm256_sub_pd(_mm256_mul_pd(z1, y2), _mm256_mul_pd(z2, y1)), area[h]);
    const __m256d dy =
        _mm256_div_pd(_mm256_sub_pd(_mm256_mul_pd(z2, x1), _mm256_mul_pd(z1, x2)), area[h]);
    _mm_store_ps(g.dzdx + 4 * h, _mm256_cvtpd_ps(dx));
    _mm_store_ps(g.dzdy + 4 * h, _mm256_cvtpd_ps(dy));
  }
  _mm256_store_ps(g.z0, z[0]);
  // Counter-clockwise lanes swap vertices 1 and 2 (the area is exact in double: 25-bit
  // differences of multiples of 2^-8).
  const __m256i ccw = lanes_where<_CMP_LT_OQ>(area);
  const __m256i x1 = _mm256_blendv_epi8(x[1], x[2], ccw), y1 = _mm256_blendv_epi8(y[1], y[2], ccw);
  x[2] = _mm256_blendv_epi8(x[2], x[1], ccw);
  y[2] = _mm256_blendv_epi8(y[2], y[1], ccw);
  x[1] = x1;
  y[1] = y1;
  for (int i = 0; i < 3; ++i) {
    _mm256_store_si256(reinterpret_cast<__m256i*>(g.x[i]), x[i]);
    _mm256_store_si256(reinterpret_cast<__m256i*>(g.y[i]), y[i]);
  }
  // Pixels whose centre 256 i + 128 lies within the vertices' bounds.
  const __m256i min_x = _mm256_min_epi32(_mm256_min_epi32(x[0], x[1]), x[2]);
  const __m256i max_x = _mm256_max_epi32(_mm256_max_epi32(x[0], x[1]), x[2]);
  const __m256i min_y = _mm256_min_epi32(_mm256_min_epi32(y[0], y[1]), y[2]);
  const __m256i max_y = _mm256_max_epi32(_mm256_max_epi32(y[0], y[1]), y[2]);
  const __m256i c127 = _mm256_set1_epi32(127), c128 = _mm256_set1_epi32(128);
  const __m256i one = _mm256_set1_epi32(1), zero = _mm256_setzero_si256();
  __m256i box[4] = {
      _mm256_max_epi32(_mm256_srai_epi32(_mm256_add_epi32(min_x, c127), 8), zero),
      _mm256_max_epi32(_mm256_srai_epi32(_mm256_add_epi32(min_y, c127), 8), zero),
      _mm256_min_epi32(_mm256_add_epi32(_mm256_srai_epi32(_mm256_sub_epi32(max_x, c128), 8), one),
                       _mm256_set1_epi32(kWidth)),
      _mm256_min_epi32(_mm256_add_epi32(_mm256_srai_epi32(_mm256_sub_epi32(max_y, c128), 8), one),
                       _mm256_set1_epi32(kHeight))};
  // Zero-area and missing lanes draw nothing.
  const __m256i flat = lanes_where<_CMP_EQ_OQ>(area);
  box[2] = _mm256_andnot_si256(flat, box[2]);
  for (int i = 0; i < 4; ++i)
    _mm256_store_si256(reinterpret_cast<__m256i*>(g.box[i]), box[i]);
  for (std::size_t l = count; l < kLanes; ++l)
    g.box[2][l] = 0;
}

__m256 clamp_unit(__m256 z) {
  return _mm256_min_ps(_mm256_max_ps(z, _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
}

// Lane l of group `g` drawn into `out`.
void draw_lane(const FloorGroup& g, int l, FloorDepth& out, std::uint64_t& passed) {
  const int x0 = g.box[0][l], y0 = g.box[1][l], x1 = g.box[2][l], y1 = g.box[3][l];
  if (x0 >= x1 || y0 >= y1) return;
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  // Each edge's G at pixel (x0 + lane, y0) (triangle_setup-inl.hpp; E in int64).
  __m256i g_row[3], step_y[3], step_x[3];
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = e == 2 ? 0 : e + 1;
    const std::int64_t a = std::int64_t{g.y[i][l]} - g.y[j][l];
    const std::int64_t b = std::int64_t{g.x[j][l]} - g.x[i][l];
    const bool top_left = a > 0 || (a == 0 && b > 0);
    const std::int64_t edge = a * ((std::int64_t{x0} * 256 + 128) - g.x[i][l]) +
                              b * ((std::int64_t{y0} * 256 + 128) - g.y[i][l]) +
                              (top_left ? 0 : -1);
    const auto ge = static_cast<std::int32_t>(edge >> 8);  // floor(edge / 256)
    g_row[e] = _mm256_add_epi32(_mm256_set1_epi32(ge),
                                _mm256_mullo_epi32(_mm256_set1_epi32(static_cast<int>(a)), lane));
    step_y[e] = _mm256_set1_epi32(static_cast<int>(b));
    step_x[e] = _mm256_set1_epi32(static_cast<int>(8 * a));
  }
  const float x_first = static_cast<float>(g.x[0][l]) * (1.0f / 256.0f);
  const float y_first = static_cast<float>(g.y[0][l]) * (1.0f / 256.0f);
  const float z0 = g.z0[l], dzdy = g.dzdy[l];
  const __m256 dzdx = _mm256_set1_ps(g.dzdx[l]);
  const __m256 centres = _mm256_setr_ps(0.5f, 1.5f, 2.5f, 3.5f, 4.5f, 5.5f, 6.5f, 7.5f);
  // dx = (px + 0.5) - x0, exact; so is each step of 8.
  const __m256 dx_first = _mm256_sub_ps(
      _mm256_add_ps(_mm256_set1_ps(static_cast<float>(x0)), centres), _mm256_set1_ps(x_first));
  const int batches = (x1 - x0 + kLanes - 1) / kLanes;
  float* row = out.depth.data() + static_cast<std::size_t>(y0) * FloorDepth::kStride + x0;
  for (int y = y0; y < y1; ++y, row += FloorDepth::kStride) {
    const float dy = (static_cast<float>(y) + 0.5f) - y_first;
    const __m256 base = _mm256_set1_ps(z0 + dzdy * dy);
    __m256i e0 = g_row[0], e1 = g_row[1], e2 = g_row[2];
    __m256 dx = dx_first;
    for (int b = 0; b < batches; ++b) {
      const __m256 outside = _mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(e0, e1), e2));
      const __m256 z = clamp_unit(_mm256_add_ps(base, _mm256_mul_ps(dzdx, dx)));
      const __m256 stored = _mm256_loadu_ps(row + kLanes * b);
      const __m256 write = _mm256_andnot_ps(outside, _mm256_cmp_ps(z, stored, _CMP_LT_OQ));
      _mm256_storeu_ps(row + kLanes * b, _mm256_blendv_ps(stored, z, write));
      passed += static_cast<std::uint64_t>(__builtin_popcount(_mm256_movemask_ps(write)));
      e0 = _mm256_add_epi32(e0, step_x[0]);
      e1 = _mm256_add_epi32(e1, step_x[1]);
      e2 = _mm256_add_epi32(e2, step_x[2]);
      dx = _mm256_add_ps(dx, _mm256_set1_ps(8.0f));
    }
    for (int e = 0; e < 3; ++e)
      g_row[e] = _mm256_add_epi32(g_row[e], step_y[e]);
  }
}

}  // namespace

void draw_exact_depth_floor(const FillrateTriangles& triangles, FloorDepth& out) {
  std::uint64_t passed = 0;
  FloorGroup group;
  const std::size_t count = triangles.triangles();
  for (std::size_t first = 0; first < count; first += kLanes) {
    set_up_group(triangles, first, std::min<std::size_t>(kLanes, count - first), group);
    for (int l = 0; l < kLanes; ++l)
      draw_lane(group, l, out, passed);
  }
  out.passed += passed;
}

}  // namespace edgewise::bench
