#include "gl_util.h"

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "interface.h"

namespace example {

GlName make_texture(GLenum format, int width, int height, int levels) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  GlName texture(id, [](GLuint n) { glDeleteTextures(1, &n); });
  glTextureStorage2D(id, levels, format, width, height);
  // Every read in the example is a texelFetch; NEAREST keeps float textures complete everywhere.
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

GlName make_framebuffer(std::initializer_list<std::pair<GLenum, GLuint>> attachments) {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  GlName framebuffer(id, [](GLuint n) { glDeleteFramebuffers(1, &n); });
  std::vector<GLenum> draw_buffers;
  for (const auto& [attachment, texture] : attachments) {
    glNamedFramebufferTexture(id, attachment, texture, 0);
    if (attachment != GL_DEPTH_ATTACHMENT) draw_buffers.push_back(attachment);
  }
  if (draw_buffers.empty()) glNamedFramebufferDrawBuffer(id, GL_NONE);  // depth only
  else glNamedFramebufferDrawBuffers(id, static_cast<GLsizei>(draw_buffers.size()), draw_buffers.data());
  if (glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("a framebuffer is incomplete");
  return framebuffer;
}

GlName make_buffer(const void* data, std::size_t bytes) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  GlName buffer(id, [](GLuint n) { glDeleteBuffers(1, &n); });
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), data, 0);
  return buffer;
}

GlName make_vertex_array(const GlName& buffer) {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  GlName vertex_array(id, [](GLuint n) { glDeleteVertexArrays(1, &n); });
  glVertexArrayVertexBuffer(id, 0, buffer.id(), 0, 3 * sizeof(float));
  glEnableVertexArrayAttrib(id, EX_POSITION_ATTRIBUTE);
  glVertexArrayAttribFormat(id, EX_POSITION_ATTRIBUTE, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(id, EX_POSITION_ATTRIBUTE, 0);
  return vertex_array;
}

GlName compile_program(const std::string& what, std::initializer_list<ShaderStage> stages) {
  GlName program(glCreateProgram(), [](GLuint n) { glDeleteProgram(n); });
  std::vector<GlName> shaders;
  for (const ShaderStage& stage : stages) {
    GlName shader(glCreateShader(stage.type), [](GLuint n) { glDeleteShader(n); });
    const std::vector<const char*>& pieces = stage.pieces;
    glShaderSource(shader.id(), static_cast<GLsizei>(pieces.size()), pieces.data(), nullptr);
    glCompileShader(shader.id());
    GLint ok = 0;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[4096] = {};
      glGetShaderInfoLog(shader.id(), sizeof log, nullptr, log);
      throw std::runtime_error(what + ": a shader does not compile:\n" + log);
    }
    glAttachShader(program.id(), shader.id());
    shaders.push_back(std::move(shader));
  }
  glLinkProgram(program.id());
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(program.id(), sizeof log, nullptr, log);
    throw std::runtime_error(what + ": the program does not link:\n" + log);
  }
  return program;
}

void check_gl(const char* step) {
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    char text[160];
    std::snprintf(text, sizeof text, "%s: GL error 0x%04x", step, error);
    throw std::runtime_error(text);
  }
}

}  // namespace example
