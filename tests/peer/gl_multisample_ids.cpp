#include "gl_multisample_ids.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <cstddef>

#include "gl/surfaceless_gl.hpp"

namespace edgewise::test {
namespace {

// Each triangle in its own colour: the packed value, unpacked to the four UNORM8 channels
// (b / 255 is converted back to b exactly).
constexpr const char* kIdVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in uint packed_color;
flat out uint color_bits;
void main() {
  gl_Position = vec4(position, 0.0, 1.0);
  color_bits = packed_color;
}
)";
constexpr const char* kIdFragmentShader = R"(#version 330 core
flat in uint color_bits;
out vec4 color;
void main() {
  uvec4 bytes = (uvec4(color_bits) >> uvec4(0u, 8u, 16u, 24u)) & 255u;
  color = vec4(bytes) / 255.0;
}
)";

// One triangle over the whole target; pixel (x, y) of the planes is sample x / width of pixel
// (x % width, y) of the multisampled texture.
constexpr const char* kPlanesVertexShader = R"(#version 330 core
void main() {
  vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  gl_Position = vec4(corner, 0.0, 1.0);
}
)";
constexpr const char* kPlanesFragmentShader = R"(#version 330 core
uniform sampler2DMS samples;
uniform int width;
out vec4 color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  color = texelFetch(samples, ivec2(p.x % width, p.y), p.x / width);
}
)";

// A framebuffer with `texture` as its one colour attachment, or 0.
GLuint framebuffer_of(GLenum target, GLuint texture) {
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, texture, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) return framebuffer;
  glDeleteFramebuffers(1, &framebuffer);
  return 0;
}

}  // namespace

std::unique_ptr<GlMultisampleIds> GlMultisampleIds::create(std::int32_t width, std::int32_t height,
                                                           int samples, std::string& why_not) {
  std::unique_ptr<GlMultisampleIds> gl(new GlMultisampleIds);
  gl->width_ = width;
  gl->height_ = height;
  gl->samples_ = samples;

  glGenTextures(1, &gl->multisampled_);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, gl->multisampled_);
  // Fixed sample locations: the same positions in every pixel, as the standard patterns.
  glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, GL_RGBA8, width, height, GL_TRUE);
  GLint granted = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &granted);
  if (glGetError() != GL_NO_ERROR || granted != samples) {
    why_not = "no RGBA8 texture of exactly " + std::to_string(samples) + " samples (got " +
              std::to_string(granted) + ")";
    return nullptr;
  }
  gl->multisampled_framebuffer_ = framebuffer_of(GL_TEXTURE_2D_MULTISAMPLE, gl->multisampled_);
  if (gl->multisampled_framebuffer_ == 0) {
    why_not = "the multisampled framebuffer is incomplete";
    return nullptr;
  }
  // The positions of the framebuffer now bound for drawing.
  for (int k = 0; k < samples; ++k) {
    GLfloat xy[2] = {};
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(k), xy);
    gl->positions_.push_back({xy[0], xy[1]});
  }

  glGenTextures(1, &gl->planes_);
  glBindTexture(GL_TEXTURE_2D, gl->planes_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width * samples, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  gl->planes_framebuffer_ = framebuffer_of(GL_TEXTURE_2D, gl->planes_);
  if (gl->planes_framebuffer_ == 0) {
    why_not = "the single-sample framebuffer is incomplete";
    return nullptr;
  }

  gl->draw_program_ = gl::link_program(kIdVertexShader, kIdFragmentShader, why_not);
  if (gl->draw_program_ == 0) return nullptr;
  gl->read_program_ = gl::link_program(kPlanesVertexShader, kPlanesFragmentShader, why_not);
  if (gl->read_program_ == 0) return nullptr;
  glUseProgram(gl->read_program_);
  glUniform1i(glGetUniformLocation(gl->read_program_, "samples"), 0);
  glUniform1i(glGetUniformLocation(gl->read_program_, "width"), width);

  glGenVertexArrays(1, &gl->vertex_array_);
  glBindVertexArray(gl->vertex_array_);
  glGenBuffers(2, gl->buffers_);
  glBindBuffer(GL_ARRAY_BUFFER, gl->buffers_[0]);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, gl->buffers_[1]);
  glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, 0, nullptr);
  glEnableVertexAttribArray(1);

  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_SAMPLE_SHADING);
  glEnable(GL_MULTISAMPLE);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  if (glGetError() != GL_NO_ERROR) {
    why_not = "setting up the targets failed with a GL error";
    return nullptr;
  }
  return gl;
}

GlMultisampleIds::~GlMultisampleIds() {
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteBuffers(2, buffers_);
  glDeleteProgram(draw_program_);
  glDeleteProgram(read_program_);
  glDeleteFramebuffers(1, &multisampled_framebuffer_);
  glDeleteFramebuffers(1, &planes_framebuffer_);
  glDeleteTextures(1, &multisampled_);
  glDeleteTextures(1, &planes_);
}

std::vector<std::uint32_t> GlMultisampleIds::draw(std::span<const Vec2> clip_xy,
                                                  std::span<const std::uint32_t> colors,
                                                  std::string& why_not) {
  // One colour per vertex, for the flat varying (all three corners alike: the provoking vertex
  // does not matter).
  std::vector<std::uint32_t> vertex_colors;
  vertex_colors.reserve(clip_xy.size());
  for (std::size_t v = 0; v < clip_xy.size(); ++v)
    vertex_colors.push_back(colors[v / 3]);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(clip_xy.size_bytes()), clip_xy.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertex_colors.size() * sizeof(std::uint32_t)),
               vertex_colors.data(), GL_STATIC_DRAW);

  glBindFramebuffer(GL_FRAMEBUFFER, multisampled_framebuffer_);
  glViewport(0, 0, width_, height_);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glUseProgram(draw_program_);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(clip_xy.size()));

  // Every sample to its own plane of the single-sample texture, then to memory.
  glBindFramebuffer(GL_FRAMEBUFFER, planes_framebuffer_);
  glViewport(0, 0, width_ * samples_, height_);
  glUseProgram(read_program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, multisampled_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const std::size_t row = std::size_t(width_) * std::size_t(samples_);
  std::vector<std::uint32_t> planes(row * std::size_t(height_));
  glReadPixels(0, 0, width_ * samples_, height_, GL_RGBA, GL_UNSIGNED_BYTE, planes.data());
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    why_not = "drawing failed with GL error " + std::to_string(error);
    return {};
  }
  // Row y of the planes holds the samples of pixel row y one after the other; reorder by sample.
  std::vector<std::uint32_t> by_sample(planes.size());
  for (std::size_t y = 0; y < std::size_t(height_); ++y) {
    for (std::size_t k = 0; k < std::size_t(samples_); ++k) {
      for (std::size_t x = 0; x < std::size_t(width_); ++x) {
        by_sample[(k * std::size_t(height_) + y) * std::size_t(width_) + x] =
            planes[y * row + k * std::size_t(width_) + x];
      }
    }
  }
  return by_sample;
}

}  // namespace edgewise::test
