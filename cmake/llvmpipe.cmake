# EGL and OpenGL for the llvmpipe peers, edgewise-bench's (bench/llvmpipe_peer.hpp) and the
# tests' (tests/peer): defines the OpenGL::EGL and OpenGL::OpenGL targets when Debian's
# libegl-dev, libgl-dev and libopengl-dev are installed (required under
# EDGEWISE_STRICT_DEPENDENCIES). llvmpipe itself (libgl1-mesa-dri) is only needed at run time:
# without it the peer's benchmarks fail with the reason instead of timing, and the tests are
# skipped with the reason.
if(TARGET OpenGL::EGL AND TARGET OpenGL::OpenGL)
  return()
endif()
# GLVND: libOpenGL for the GL entry points and libEGL for the context, no GLX.
set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL QUIET COMPONENTS OpenGL EGL ${EDGEWISE_REQUIRED_IF_STRICT})
