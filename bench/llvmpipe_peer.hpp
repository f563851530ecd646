// Mesa's llvmpipe as a drawing peer: an OpenGL 3.3 core context on EGL's surfaceless platform
// (EGL_MESA_platform_surfaceless: no window system; EGL_KHR_surfaceless_context: current without
// a surface), drawing into a framebuffer object of kWidth x kHeight with GL_RGBA8 colour and
// GL_DEPTH_COMPONENT32F depth, of the workload's samples per pixel (multisampled renderbuffers
// for more than one). A multisampled target is drawn only where the driver offers that many
// samples (GL_MAX_SAMPLES: 4 in Mesa 22.3's llvmpipe) at exactly the positions of edgewise's
// standard pattern, seen through the vertical flip below; it is not resolved, as edgewise's
// draw() does not resolve.
//
// It draws a PeerWorkload from the same vertex arrays, uploaded once, with the same transform:
// - clip space as edgewise's (camera.hpp): GL_ARB_clip_control's GL_ZERO_TO_ONE makes window
//   depth z/w, and the viewport maps NDC onto the whole target;
// - the picture flipped vertically: the vertex shader negates clip y, so GL's window row y (rows
//   counted from the bottom) is edgewise's row y (counted from the top). llvmpipe's fill rule,
//   applied to its own rows, then matches edgewise's top-left rule: the covered counts agree
//   (without the flip, pixel centres exactly on an edge are decided the other way);
// - Gouraud (the shading workload): the vertex colours, interpolated (edgewise's Gouraud has no
//   lighting; that is Shading::diffuse);
// - diffuse (the real meshes): white vertices lit per pixel by the renormalized interpolated
//   normal, as Shading::diffuse; indexed meshes through an element buffer; back faces culled
//   (edgewise's windings are on its y-down screen, GL's opposite after the flip);
// - textured (flat white shading times the texture): the texture's own mip levels, filtered with
//   GL_LINEAR_MIPMAP_LINEAR and GL_REPEAT, as edgewise's trilinear filter; for edgewise's
//   anisotropic filter, with GL_TEXTURE_MAX_ANISOTROPY set to its max_anisotropy as well
//   (GL_ARB_texture_filter_anisotropic, which llvmpipe offers up to 16 in Mesa 22.3). GL leaves
//   the anisotropic filter's form to the driver: the two do the same kind of work (up to that
//   many probes along the footprint's major axis), not the same arithmetic.
// load() refuses other settings.
//
// llvmpipe reads its settings (LP_NUM_THREADS among them) from the environment when EGL creates
// its screen, once per process: draw_peer_bench.cpp runs each setting in a process of its own.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "draw/draw_peer_workloads.hpp"

namespace edgewise::bench {

struct PeerDrawTime {
  double wall = 0.0;  // seconds
  double cpu = 0.0;   // seconds of CPU time, all of the process's threads together
};

struct PeerCounts {
  std::uint64_t covered = 0;  // samples of the triangles inside the target
  std::uint64_t written = 0;  // of those, passing the depth test
};

class LlvmpipePeer {
 public:
  // The context, or nullptr with the reason in `error`: no EGL or no surfaceless platform, no
  // OpenGL 3.3 core context, GL_ARB_clip_control missing, or a GL_RENDERER that does not start
  // with "llvmpipe".
  static std::unique_ptr<LlvmpipePeer> create(std::string& error);
  ~LlvmpipePeer();
  LlvmpipePeer(const LlvmpipePeer&) = delete;
  LlvmpipePeer& operator=(const LlvmpipePeer&) = delete;

  const std::string& renderer() const { return renderer_; }

  // Makes the target of the workload's sample count, uploads its vertices and texture and builds
  // its program; false with the reason (a sample count or pattern the driver does not offer, a
  // setting the peer does not reproduce, a GL error).
  bool load(const PeerWorkload& workload, std::string& error);

  // Occlusion queries (GL_SAMPLES_PASSED) over one draw each into the cleared target: with the
  // depth test passing everything and writing nothing (covered), then with the workload's test
  // (written).
  PeerCounts count();

  // One timed draw: the target cleared and the clear finished untimed, as edgewise's benchmarks
  // clear with the timer paused; then the draw and glFinish().
  PeerDrawTime timed_draw();

 private:
  struct Context;
  explicit LlvmpipePeer(std::unique_ptr<Context> context);
  void clear();
  void draw();

  std::unique_ptr<Context> context_;
  std::string renderer_;
};

// The child process's side of draw_peer_bench.cpp: serves requests on `fd` (peer_process.hpp)
// until it closes. Returns the process's exit status.
int serve_llvmpipe_peer(int fd);

}  // namespace edgewise::bench
