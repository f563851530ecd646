// An OpenGL 3.3 core context on EGL's surfaceless platform, current on the calling thread, in
// this process: how the llvmpipe peers (edgewise-bench's DrawPeer/ and tests/peer) reach Mesa's
// llvmpipe without a display. It has no window; everything is drawn into framebuffer objects.
// And the shader programs both build.
#pragma once

#include <EGL/egl.h>

#include <memory>
#include <string>

namespace edgewise::gl {

class SurfacelessGl {
 public:
  // The context, made current; or null, with `why_not` saying what this machine lacks.
  // Asks Mesa for its software renderer (LIBGL_ALWAYS_SOFTWARE=1, unless already set).
  static std::unique_ptr<SurfacelessGl> create(std::string& why_not);
  ~SurfacelessGl();
  SurfacelessGl(const SurfacelessGl&) = delete;
  SurfacelessGl& operator=(const SurfacelessGl&) = delete;

  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& renderer() const { return renderer_; }

 private:
  SurfacelessGl() = default;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string renderer_;
};

// The program (a GLuint) of a vertex and a fragment shader (GLSL source) in the current
// context, or 0 with `why_not` holding the compiler's or linker's log.
unsigned link_program(const char* vertex_source, const char* fragment_source, std::string& why_not);

}  // namespace edgewise::gl
