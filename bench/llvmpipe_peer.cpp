#include "llvmpipe_peer.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <time.h>

#include <chrono>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "benchmarks.hpp"
#include "gl/surfaceless_gl.hpp"
#include "edgewise/multisample.hpp"

namespace edgewise::bench {
namespace {

double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

bool has_gl_extension(std::string_view name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (extension != nullptr && name == extension) return true;
  }
  return false;
}

GLenum gl_depth_function(DepthTest test) {
  switch (test) {
    case DepthTest::less:
      return GL_LESS;
    case DepthTest::less_equal:
      return GL_LEQUAL;
    case DepthTest::greater:
      return GL_GREATER;
    case DepthTest::always:
      return GL_ALWAYS;
    case DepthTest::never:
      return GL_NEVER;
  }
  return GL_LESS;
}

// Gouraud: the vertex colour, interpolated.
constexpr const char* kColorVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;
uniform mat4 to_clip;
out vec4 shade;
void main() {
  gl_Position = to_clip * vec4(position, 1.0);
  shade = color;
}
)";
constexpr const char* kColorFragmentShader = R"(#version 330 core
in vec4 shade;
out vec4 pixel;
void main() { pixel = shade; }
)";

// Textured with white flat shading: the filtered texel.
constexpr const char* kTextureVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
uniform mat4 to_clip;
out vec2 st;
void main() {
  gl_Position = to_clip * vec4(position, 1.0);
  st = uv;
}
)";
constexpr const char* kTextureFragmentShader = R"(#version 330 core
uniform sampler2D image;
in vec2 st;
out vec4 pixel;
void main() { pixel = texture(image, st); }
)";

// Per-pixel diffuse on white vertices, as edgewise's Shading::diffuse: the interpolated normal,
// renormalized, lights the pixel by ambient + (1 - ambient) max(0, n . l).
constexpr const char* kDiffuseVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 to_clip;
out vec3 n;
void main() {
  gl_Position = to_clip * vec4(position, 1.0);
  n = normal;
}
)";
constexpr const char* kDiffuseFragmentShader = R"(#version 330 core
uniform vec3 light;
uniform float ambient;
in vec3 n;
out vec4 pixel;
void main() {
  float len = length(n);
  float lambert = len > 0.0 ? max(dot(n, light) / len, 0.0) : 0.0;
  pixel = vec4(vec3(ambient + (1.0 - ambient) * lambert), 1.0);
}
)";

template <class T>
void upload_attribute(GLuint buffer, GLuint location, std::span<const T> values) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(values.size() * sizeof(T)), values.data(),
               GL_STATIC_DRAW);
  glVertexAttribPointer(location, GLint(sizeof(T) / sizeof(float)), GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(location);
}

// Why the peer would not draw what edgewise draws, or empty.
std::string unsupported(const PeerWorkload& workload) {
  const DrawMesh& mesh = workload.mesh;
  const DrawOptions& o = workload.options;
  if (o.scissor) return "a scissor";
  if (o.interpolation != InterpolationMethod::plane_equations ||
      o.perspective != Perspective::correct) {
    return "interpolation other than plane equations, perspective-correct";
  }
  if (!o.texture) {
    if (o.shading == Shading::gouraud && !mesh.colors.empty()) return {};
    if (o.shading == Shading::diffuse && mesh.colors.empty() && !mesh.normals.empty()) return {};
    return "shading other than Gouraud or diffuse on white vertices";
  }
  const Texture& texture = *o.texture->texture;
  const SamplerOptions& sampler = o.texture->sampler;
  if (o.shading != Shading::flat || !mesh.colors.empty()) return "textures on shaded colours";
  if (texture.format() != TexelFormat::rgba8 || texture.encoding() != ColorEncoding::linear)
    return "textures other than linear RGBA8";
  if ((sampler.filter != TextureFilter::trilinear &&
       sampler.filter != TextureFilter::anisotropic) ||
      sampler.wrap_s != WrapMode::repeat || sampler.wrap_t != WrapMode::repeat ||
      sampler.lod != LodFormula::exact || sampler.lod_bias != 0.0f ||
      o.texture->derivatives != TextureDerivatives::quad) {
    return "sampling other than trilinear or anisotropic, repeat, without bias, with quad "
           "derivatives";
  }
  return {};
}

// Whether the bound framebuffer's samples lie where edgewise's standard pattern of `count` puts
// them, in the frame the peer draws in; the reason when not, or empty. The vertex shader negates
// clip y, so GL's window y (lower-left origin) is edgewise's screen y (y down): a GL position
// (gx, gy) in its pixel (glGetMultisamplefv, from the pixel's corner at the smaller window y) is
// the offset (16 gx - 8, 16 gy - 8) sixteenths from the centre, y down, in edgewise's terms.
// Only the set matters: the benchmark compares counts of covered samples, not which ones. Mesa
// 22.3's llvmpipe gives exactly the standard 4x pattern (tests/peer/llvmpipe_multisample_test.cpp
// proves sample-by-sample agreement). Any other set would decide other samples and the counts
// could not be compared.
std::string standard_positions(int count) {
  if (count == 1) return {};  // pixel centres
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  const std::span<const SampleOffset> pattern = standard_sample_pattern(count);
  std::vector<bool> taken(pattern.size(), false);
  std::string found;
  bool all_matched = samples == count;
  for (GLint g = 0; g < samples; ++g) {
    GLfloat p[2] = {};
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(g), p);
    found += " (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ")";
    bool matched = false;
    for (std::size_t k = 0; k < pattern.size() && !matched; ++k) {
      if (!taken[k] && p[0] * 16.0f - 8.0f == float(pattern[k].x) &&
          p[1] * 16.0f - 8.0f == float(pattern[k].y)) {
        taken[k] = matched = true;
      }
    }
    all_matched = all_matched && matched;
  }
  if (all_matched) return {};
  return "the " + std::to_string(count) + "x sample positions," + found +
         ", are not the standard pattern in the benchmark's frame: the covered samples would "
         "differ";
}

}  // namespace

struct LlvmpipePeer::Context {
  std::unique_ptr<gl::SurfacelessGl> gl;  // destroyed after the objects below
  GLuint framebuffer = 0, color = 0, depth = 0, query = 0;
  // The loaded workload.
  GLuint vertex_array = 0, buffers[3] = {}, program = 0, texture = 0;
  GLsizei vertices = 0;  // or indices, when indexed
  bool indexed = false;
  GLenum depth_function = GL_LESS;
  bool depth_write = true;
  Vec4 clear_color{};
  float clear_depth = 1.0f;

  int samples = 0;  // of the target's renderbuffers; 0 while there is none

  void release_target() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &color);
    glDeleteRenderbuffers(1, &depth);
    framebuffer = color = depth = 0;
    samples = 0;
  }

  // The kWidth x kHeight RGBA8 + DEPTH_COMPONENT32F target with `count` samples per pixel, bound;
  // false with the reason.
  bool make_target(int count, std::string& error) {
    if (samples == count) return true;
    release_target();
    GLint most = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &most);
    if (count > 1 && most < count) {
      error = "at most " + std::to_string(most) + " samples per pixel (GL_MAX_SAMPLES), " +
              std::to_string(count) + " needed";
      return false;
    }
    // glRenderbufferStorageMultisample with 0 samples is the single-sample storage.
    const GLsizei storage_samples = count > 1 ? count : 0;
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, storage_samples, GL_RGBA8, kWidth, kHeight);
    GLint allocated = 0;  // a driver may give more samples than asked
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &allocated);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, storage_samples, GL_DEPTH_COMPONENT32F,
                                     kWidth, kHeight);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    const std::string what = "the RGBA8 + DEPTH_COMPONENT32F framebuffer of " +
                             std::to_string(count) + " sample" + (count > 1 ? "s" : "");
    if (glGetError() != GL_NO_ERROR ||
        glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      error = what + " is incomplete";
      release_target();
      return false;
    }
    if (allocated != storage_samples) {
      error = what + " got " + std::to_string(allocated) + " samples per pixel";
      release_target();
      return false;
    }
    if (const std::string positions = standard_positions(count); !positions.empty()) {
      error = positions;
      release_target();
      return false;
    }
    samples = count;
    return true;
  }

  void release_workload() {
    glDeleteVertexArrays(1, &vertex_array);
    glDeleteBuffers(3, buffers);
    glDeleteProgram(program);
    glDeleteTextures(1, &texture);
    vertex_array = buffers[0] = buffers[1] = buffers[2] = program = texture = 0;
    vertices = 0;
    indexed = false;
    glDisable(GL_CULL_FACE);
  }

  ~Context() {
    if (gl) {
      release_workload();
      glDeleteQueries(1, &query);
      glDeleteFramebuffers(1, &framebuffer);
      glDeleteRenderbuffers(1, &color);
      glDeleteRenderbuffers(1, &depth);
    }
  }
};

LlvmpipePeer::LlvmpipePeer(std::unique_ptr<Context> context) : context_(std::move(context)) {}
LlvmpipePeer::~LlvmpipePeer() = default;

std::unique_ptr<LlvmpipePeer> LlvmpipePeer::create(std::string& error) {
  auto c = std::make_unique<Context>();
  c->gl = gl::SurfacelessGl::create(error);
  if (!c->gl) return nullptr;
  const std::string name = c->gl->renderer();
  if (name.rfind("llvmpipe", 0) != 0) {
    error = "GL_RENDERER is \"" + name + "\", not llvmpipe";
    return nullptr;
  }
  if (!has_gl_extension("GL_ARB_clip_control")) {
    error = name + " has no GL_ARB_clip_control";
    return nullptr;
  }

  if (!c->make_target(1, error)) return nullptr;
  glGenQueries(1, &c->query);
  // Clip space as edgewise's (camera.hpp): 0 <= z <= w, window depth z/w.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDepthRange(0.0, 1.0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_MULTISAMPLE);  // the default; multisampled targets then rasterize per sample
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  if (glGetError() != GL_NO_ERROR) {
    error = "setting up the framebuffer failed";
    return nullptr;
  }
  auto peer = std::unique_ptr<LlvmpipePeer>(new LlvmpipePeer(std::move(c)));
  peer->renderer_ = name;
  return peer;
}

bool LlvmpipePeer::load(const PeerWorkload& workload, std::string& error) {
  Context& c = *context_;
  c.release_workload();
  if (const std::string what = unsupported(workload); !what.empty()) {
    error = "the GL peer does not draw " + what;
    return false;
  }
  if (!c.make_target(workload.samples, error)) {
    error = renderer_ + ": " + error;
    return false;
  }
  const DrawMesh& mesh = workload.mesh;
  const DrawOptions& options = workload.options;
  const bool textured = options.texture.has_value();
  const bool diffuse = !textured && options.shading == Shading::diffuse;
  c.program = textured  ? gl::link_program(kTextureVertexShader, kTextureFragmentShader, error)
              : diffuse ? gl::link_program(kDiffuseVertexShader, kDiffuseFragmentShader, error)
                        : gl::link_program(kColorVertexShader, kColorFragmentShader, error);
  if (c.program == 0) return false;
  glUseProgram(c.program);
  Mat4 to_clip = options.transform;
  for (float& m : to_clip.m[1])
    m = -m;  // the vertical flip
  // edgewise's Mat4 is row-major: GL transposes it.
  glUniformMatrix4fv(glGetUniformLocation(c.program, "to_clip"), 1, GL_TRUE, &to_clip.m[0][0]);

  glGenVertexArrays(1, &c.vertex_array);
  glBindVertexArray(c.vertex_array);
  glGenBuffers(3, c.buffers);
  upload_attribute(c.buffers[0], 0, mesh.positions);
  if (textured) {
    upload_attribute(c.buffers[1], 1, mesh.uvs);
  } else if (diffuse) {
    upload_attribute(c.buffers[1], 1, mesh.normals);
    const Vec3 l = options.light_direction;
    glUniform3f(glGetUniformLocation(c.program, "light"), l.x, l.y, l.z);
    glUniform1f(glGetUniformLocation(c.program, "ambient"), options.ambient);
  } else {
    upload_attribute(c.buffers[1], 1, mesh.colors);
  }
  c.indexed = !mesh.indices.empty();
  if (c.indexed) {
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, c.buffers[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
  }
  c.vertices = GLsizei(c.indexed ? mesh.indices.size() : mesh.positions.size());
  // edgewise's windings are on its screen (y down); after the vertical flip GL's window
  // coordinates are the same numbers read y up, so each winding is GL's opposite: edgewise's
  // clockwise is GL's counter-clockwise.
  if (options.cull != CullMode::none) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(options.cull == CullMode::clockwise ? GL_CW : GL_CCW);
  }

  if (textured) {
    const Texture& texture = *options.texture->texture;
    glGenTextures(1, &c.texture);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, c.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const auto levels = texture.mip_levels();
    for (std::size_t i = 0; i < levels.size(); ++i) {
      glTexImage2D(GL_TEXTURE_2D, GLint(i), GL_RGBA8, levels[i].width, levels[i].height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, texture.texels(levels[i]));
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(levels.size() - 1));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    const SamplerOptions& sampler = options.texture->sampler;
    if (sampler.filter == TextureFilter::anisotropic) {
      // GL_ARB_texture_filter_anisotropic: up to GL_TEXTURE_MAX_ANISOTROPY samples along the
      // footprint's major axis, as edgewise's anisotropic filter takes max_anisotropy probes.
      GLfloat most = 0.0f;
      glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &most);
      if (!has_gl_extension("GL_ARB_texture_filter_anisotropic") ||
          most < GLfloat(sampler.max_anisotropy)) {
        error = renderer_ + " has no anisotropic filtering up to " +
                std::to_string(sampler.max_anisotropy) + " samples (largest " +
                std::to_string(most) + ")";
        return false;
      }
      glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, GLfloat(sampler.max_anisotropy));
    }
    glUniform1i(glGetUniformLocation(c.program, "image"), 0);
  }

  glViewport(0, 0, kWidth, kHeight);
  c.depth_function = gl_depth_function(options.depth_test);
  c.depth_write = options.depth_write;
  c.clear_color = workload.clear_color;
  c.clear_depth = workload.clear_depth;
  glFinish();
  if (glGetError() != GL_NO_ERROR) {
    error = "uploading the workload failed";
    return false;
  }
  return true;
}

void LlvmpipePeer::clear() {
  const Context& c = *context_;
  glDepthMask(GL_TRUE);
  glClearColor(c.clear_color.x, c.clear_color.y, c.clear_color.z, c.clear_color.w);
  glClearDepth(c.clear_depth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void LlvmpipePeer::draw() {
  if (context_->indexed) {
    glDrawElements(GL_TRIANGLES, context_->vertices, GL_UNSIGNED_INT, nullptr);
  } else {
    glDrawArrays(GL_TRIANGLES, 0, context_->vertices);
  }
}

PeerCounts LlvmpipePeer::count() {
  const Context& c = *context_;
  const auto samples_passed = [&](GLenum function, GLboolean write) {
    clear();
    glDepthFunc(function);
    glDepthMask(write);
    glBeginQuery(GL_SAMPLES_PASSED, c.query);
    draw();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 samples = 0;
    glGetQueryObjectui64v(c.query, GL_QUERY_RESULT, &samples);
    return std::uint64_t(samples);
  };
  PeerCounts counts;
  counts.covered = samples_passed(GL_ALWAYS, GL_FALSE);
  counts.written = samples_passed(c.depth_function, c.depth_write ? GL_TRUE : GL_FALSE);
  return counts;
}

PeerDrawTime LlvmpipePeer::timed_draw() {
  clear();
  glFinish();
  glDepthFunc(context_->depth_function);
  glDepthMask(context_->depth_write ? GL_TRUE : GL_FALSE);
  const double cpu_start = process_cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  draw();
  glFinish();
  PeerDrawTime time;
  time.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  time.cpu = process_cpu_seconds() - cpu_start;
  return time;
}

}  // namespace edgewise::bench
