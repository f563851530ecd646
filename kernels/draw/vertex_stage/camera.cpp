#include "edgewise/camera.hpp"

#include <cmath>

namespace edgewise {
namespace {

// Camera matrices are set up in double and rounded once, so each entry is the float nearest
// its exact value.
struct Mat4d {
  double m[4][4] = {};
  Mat4 rounded() const {
    Mat4 out{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        out.m[r][c] = static_cast<float>(m[r][c]);
    return out;
  }
};

struct Vec3d {
  double x, y, z;
};

Vec3d widen(const Vec3& v) {
  return {v.x, v.y, v.z};
}
Vec3d operator-(const Vec3d& a, const Vec3d& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
double dot(const Vec3d& a, const Vec3d& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3d normalize(const Vec3d& v) {
  const double length = std::sqrt(dot(v, v));
  return {v.x / length, v.y / length, v.z / length};
}

}  // namespace

Mat4 identity() {
  Mat4 out{};
  for (int i = 0; i < 4; ++i)
    out.m[i][i] = 1.0f;
  return out;
}

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 out{};
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      float sum = 0.0f;
      for (int k = 0; k < 4; ++k)
        sum += a.m[r][k] * b.m[k][c];
      out.m[r][c] = sum;
    }
  }
  return out;
}

Mat4 translate(const Vec3& offset) {
  Mat4 out = identity();
  out.m[0][3] = offset.x;
  out.m[1][3] = offset.y;
  out.m[2][3] = offset.z;
  return out;
}

Mat4 scale(const Vec3& factors) {
  Mat4 out = identity();
  out.m[0][0] = factors.x;
  out.m[1][1] = factors.y;
  out.m[2][2] = factors.z;
  return out;
}

Mat4 rotate(const Vec3& axis, float radians) {
  const Vec3d a = widen(axis);
  const double length = std::sqrt(dot(a, a));
  if (!(length > 0.0)) return identity();
  const Vec3d u{a.x / length, a.y / length, a.z / length};
  const double c = std::cos(static_cast<double>(radians));
  const double s = std::sin(static_cast<double>(radians));
  const double t = 1.0 - c;
  // Rodrigues' rotation formula.
  Mat4d out;
  out.m[0][0] = c + u.x * u.x * t;
  out.m[0][1] = u.x * u.y * t - u.z * s;
  out.m[0][2] = u.x * u.z * t + u.y * s;
  out.m[1][0] = u.y * u.x * t + u.z * s;
  out.m[1][1] = c + u.y * u.y * t;
  out.m[1][2] = u.y * u.z * t - u.x * s;
  out.m[2][0] = u.z * u.x * t - u.y * s;
  out.m[2][1] = u.z * u.y * t + u.x * s;
  out.m[2][2] = c + u.z * u.z * t;
  out.m[3][3] = 1.0;
  return out.rounded();
}

Vec4 transform(const Mat4& m, const Vec3& p) {
  return transform(m, Vec4{p.x, p.y, p.z, 1.0f});
}

Vec4 transform(const Mat4& m, const Vec4& p) {
  float out[4];
  for (int r = 0; r < 4; ++r)
    out[r] = m.m[r][0] * p.x + m.m[r][1] * p.y + m.m[r][2] * p.z + m.m[r][3] * p.w;
  return {out[0], out[1], out[2], out[3]};
}

Mat4 perspective(float fovy_radians, float aspect, float near, float far) {
  const double f = 1.0 / std::tan(0.5 * static_cast<double>(fovy_radians));
  const double n = near, fa = far;
  Mat4d out;
  out.m[0][0] = f / static_cast<double>(aspect);
  out.m[1][1] = f;
  // z_clip = (far z + near far) / (near - far): 0 at z = -near, w = far at z = -far.
  out.m[2][2] = fa / (n - fa);
  out.m[2][3] = n * fa / (n - fa);
  out.m[3][2] = -1.0;
  return out.rounded();
}

Mat4 orthographic(float left, float right, float bottom, float top, float near, float far) {
  const double l = left, r = right, b = bottom, t = top, n = near, f = far;
  Mat4d out;
  out.m[0][0] = 2.0 / (r - l);
  out.m[0][3] = -(r + l) / (r - l);
  out.m[1][1] = 2.0 / (t - b);
  out.m[1][3] = -(t + b) / (t - b);
  // z_clip = -(z + near) / (far - near): 0 at z = -near, 1 at z = -far.
  out.m[2][2] = -1.0 / (f - n);
  out.m[2][3] = -n / (f - n);
  out.m[3][3] = 1.0;
  return out.rounded();
}

Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3d e = widen(eye);
  const Vec3d forward = normalize(widen(target) - e);
  const Vec3d right = normalize(cross(forward, widen(up)));
  const Vec3d true_up = cross(right, forward);
  // Rows are the camera's axes in world space; the camera looks down its -z (= forward).
  Mat4d out;
  const Vec3d rows[3] = {right, true_up, {-forward.x, -forward.y, -forward.z}};
  for (int r = 0; r < 3; ++r) {
    out.m[r][0] = rows[r].x;
    out.m[r][1] = rows[r].y;
    out.m[r][2] = rows[r].z;
    out.m[r][3] = -dot(rows[r], e);
  }
  out.m[3][3] = 1.0;
  return out.rounded();
}

ScreenVertex to_screen(const Vec4& clip, const Viewport& viewport) {
  const float inv_w = 1.0f / clip.w;
  const float half_width = 0.5f * static_cast<float>(viewport.width);
  const float half_height = 0.5f * static_cast<float>(viewport.height);
  float depth = clip.z * inv_w;
  // z <= w can still give z * (1/w) one rounding above 1.
  depth = depth > 1.0f ? 1.0f : depth;
  depth = depth < 0.0f ? 0.0f : depth;
  return {(clip.x * inv_w + 1.0f) * half_width, (1.0f - clip.y * inv_w) * half_height, depth,
          inv_w};
}

}  // namespace edgewise
