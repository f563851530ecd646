#define GL_GLEXT_PROTOTYPES 1
#include "gl/surfaceless_gl.hpp"

#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <cstdlib>
#include <string_view>

namespace edgewise::gl {
namespace {

// Whether the space-separated `list` (an EGL extension string) holds `word`.
bool lists(const char* list, std::string_view word) {
  if (list == nullptr) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const std::size_t end = rest.find(' ');
    if (rest.substr(0, end) == word) return true;
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + 1);
  }
  return false;
}

GLuint compile(GLenum stage, const char* source, std::string& why_not) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  char log[1024] = {};
  glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  why_not = std::string("a shader does not compile: ") + log;
  glDeleteShader(shader);
  return 0;
}

}  // namespace

unsigned link_program(const char* vertex_source, const char* fragment_source,
                      std::string& why_not) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source, why_not);
  const GLuint fragment = vertex != 0 ? compile(GL_FRAGMENT_SHADER, fragment_source, why_not) : 0;
  if (fragment == 0) {
    glDeleteShader(vertex);
    return 0;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok == GL_TRUE) return program;
  char log[1024] = {};
  glGetProgramInfoLog(program, sizeof log, nullptr, log);
  why_not = std::string("a program does not link: ") + log;
  glDeleteProgram(program);
  return 0;
}

std::unique_ptr<SurfacelessGl> SurfacelessGl::create(std::string& why_not) {
  // Mesa reads it when the display is initialized: on a machine with a GPU, the surfaceless
  // platform would otherwise pick the GPU's driver.
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  std::unique_ptr<SurfacelessGl> gl(new SurfacelessGl);
  // The client extensions (EGL_EXT_client_extensions) name the platforms libEGL offers.
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!lists(client, "EGL_EXT_platform_base") || !lists(client, "EGL_MESA_platform_surfaceless")) {
    why_not = "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)";
    return nullptr;
  }
  const auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (platform_display == nullptr) {
    why_not = "EGL has no eglGetPlatformDisplayEXT";
    return nullptr;
  }
  gl->display_ = platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (gl->display_ == EGL_NO_DISPLAY || eglInitialize(gl->display_, nullptr, nullptr) != EGL_TRUE) {
    gl->display_ = EGL_NO_DISPLAY;
    why_not = "EGL's surfaceless display does not initialize (is libgl1-mesa-dri installed?)";
    return nullptr;
  }
  if (!lists(eglQueryString(gl->display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    why_not = "the EGL display has no EGL_KHR_surfaceless_context";
    return nullptr;
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    why_not = "EGL has no desktop OpenGL";
    return nullptr;
  }
  // The surfaceless platform offers pbuffer configs only, which the default EGL_WINDOW_BIT would
  // exclude; the config's own buffers are never used.
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                      EGL_DONT_CARE, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (eglChooseConfig(gl->display_, config_attributes, &config, 1, &configs) != EGL_TRUE ||
      configs < 1) {
    why_not = "no EGL config renders OpenGL";
    return nullptr;
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  gl->context_ = eglCreateContext(gl->display_, config, EGL_NO_CONTEXT, context_attributes);
  if (gl->context_ == EGL_NO_CONTEXT) {
    why_not = "EGL gives no OpenGL 3.3 core context";
    return nullptr;
  }
  if (eglMakeCurrent(gl->display_, EGL_NO_SURFACE, EGL_NO_SURFACE, gl->context_) != EGL_TRUE) {
    why_not = "eglMakeCurrent without a surface failed";
    return nullptr;
  }
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  gl->renderer_ = renderer != nullptr ? renderer : "";
  return gl;
}

SurfacelessGl::~SurfacelessGl() {
  if (context_ != EGL_NO_CONTEXT) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
  if (display_ != EGL_NO_DISPLAY) eglTerminate(display_);
}

}  // namespace edgewise::gl
