// view_mesh(): drawn with perspective-correct interpolation, the two triangles give every pixel
// the view's own query. Checked through the texture-coordinate formula draw() uses
// (kernels/draw/shading/texture_planes.hpp) on the screen triangle draw() derives from the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "edgewise/camera.hpp"
#include "draw/shading/texture_planes.hpp"
#include "texture_scene/builtin_views.hpp"
#include "texture_scene/view_mesh.hpp"

namespace edgewise::texture_scene {
namespace {

// The first triangle as the shading kernels receive it: transformed, mapped to the screen,
// snapped to 1/256 px. Its planes extend over the whole screen (both triangles lie on one
// projective mapping).
detail::TexturePlanes first_triangle_planes(const ViewMesh& mesh, const TextureView& view) {
  Vec2 p[3], uv[3];
  double w[3];
  for (int i = 0; i < 3; ++i) {
    const Vec4 clip = transform(mesh.transform, mesh.positions[i]);
    const ScreenVertex s = to_screen(clip, Viewport{view.width(), view.height()});
    p[i] = {static_cast<float>(std::nearbyint(s.x * 256.0) / 256.0),
            static_cast<float>(std::nearbyint(s.y * 256.0) / 256.0)};
    uv[i] = mesh.uvs[i];
    w[i] = clip.w;
  }
  return detail::make_texture_planes(p, uv, w, Perspective::correct);
}

// The sum of a plane's terms' magnitudes at pixel (i, j), which scales its rounding errors.
double terms(const detail::TexturePlanes& planes, const detail::AttributePlane& plane,
             std::int32_t i, std::int32_t j) {
  const double dx = detail::offset_x(planes, i), dy = detail::offset_y(planes, j);
  return std::abs(plane.at_vertex) + std::abs(plane.dy * dy) + std::abs(plane.dx * dx);
}

// Bounds, per pixel: the corners' uv and w are rounded to float (2^-24 each), each plane's
// setup rounds its three coefficients once and its evaluation three times, each at most u = 2^-24
// times the sum M of its terms' magnitudes: the plane of s/w is off by at most about 8 u M_s,
// that of q by 8 u M_q; s = (s/w) r with r = 1/q is then off by (8 u M_s + |s| 8 u M_q) |r| plus
// two roundings of s. The tests allow 16 u instead of 8 u (the corners' own roundings move
// the setup too). A derivative (A - s Q) r adds the slopes' errors, at most 16 u times the
// terms they came from relative to q's (M_q / |q|), on top of the same for s: bounded by
// 32 u (|A| + |s| |Q|) |r| M_q / |q| + |Q| |r| times the error of s.
TEST(ViewMesh, DrawnMappingIsTheViewsMapping) {
  constexpr double u = 0x1p-24;
  for (const TextureView& view :
       {ground_plane_view(480, 270), magnification_view(320, 200, 64, 64)}) {
    const ViewMesh mesh = view_mesh(view);
    ASSERT_EQ(mesh.positions.size(), 6u);
    const detail::TexturePlanes planes = first_triangle_planes(mesh, view);
    ASSERT_TRUE(planes.divides);
    double worst = 0.0;  // the largest error as a fraction of its bound
    for (std::int32_t j = 0; j < view.height(); j += 3) {
      for (std::int32_t i = 0; i < view.width(); i += 5) {
        const TextureQuery want = view.query(i, j);
        const TextureQuery got = detail::texture_query(planes, TextureDerivatives::analytic, i, j);
        const double m_q = terms(planes, planes.q, i, j);
        const double q = m_q > 0 ? planes.q.at_vertex + planes.q.dy * detail::offset_y(planes, j) +
                                       planes.q.dx * detail::offset_x(planes, i)
                                 : 1.0;
        const double r = std::abs(1.0 / q), amplification = m_q / std::abs(q);
        const double st[2][2] = {{got.s, want.s}, {got.t, want.t}};
        const detail::AttributePlane* numerators[2] = {&planes.s, &planes.t};
        const double derivatives[2][2][2] = {{{got.dsdx, want.dsdx}, {got.dsdy, want.dsdy}},
                                             {{got.dtdx, want.dtdx}, {got.dtdy, want.dtdy}}};
        for (int k = 0; k < 2; ++k) {
          const double value = std::abs(st[k][1]);
          const double position_bound =
              (16 * u * terms(planes, *numerators[k], i, j) + value * 16 * u * m_q) * r +
              2 * u * value;
          worst = std::max(worst, std::abs(st[k][0] - st[k][1]) / position_bound);
          const double slopes[2][2] = {{numerators[k]->dx, planes.q.dx},
                                       {numerators[k]->dy, planes.q.dy}};
          for (int axis = 0; axis < 2; ++axis) {
            const double a = std::abs(slopes[axis][0]), q_slope = std::abs(slopes[axis][1]);
            const double bound =
                32 * u * (a + value * q_slope) * r * amplification + q_slope * r * position_bound;
            worst = std::max(worst,
                             std::abs(derivatives[k][axis][0] - derivatives[k][axis][1]) / bound);
          }
        }
      }
    }
    EXPECT_LE(worst, 1.0);
  }
}

}  // namespace
}  // namespace edgewise::texture_scene
