#include "gl/texture.h"

#include <cstdio>

#include "core/error.h"

namespace pn {
namespace {

GLenum pixel_format(int channels) {
  static const GLenum formats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
  return formats[channels - 1];
}

void check_size(const Context& context, int width, int height) {
  GLint max_size = 0;
  context.gl().GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw Error("texture size " + std::to_string(width) + "x" + std::to_string(height) +
                ": expected 1 to GL_MAX_TEXTURE_SIZE (" + std::to_string(max_size) + ") on each side");
}

// Binds a texture on the active unit for as long as this lives (bind-to-edit), then puts back
// what was bound there: an edit never disturbs a pass's PassBindings.
class BoundTexture {
 public:
  BoundTexture(const GladGLContext& gl, const GlObject& texture) : gl_(gl), target_(texture.target()) {
    gl_.GetIntegerv(target_ == GL_TEXTURE_2D_ARRAY ? GL_TEXTURE_BINDING_2D_ARRAY : GL_TEXTURE_BINDING_2D, &previous_);
    gl_.BindTexture(target_, texture.id());
  }
  ~BoundTexture() { gl_.BindTexture(target_, static_cast<GLuint>(previous_)); }
  BoundTexture(const BoundTexture&) = delete;
  BoundTexture& operator=(const BoundTexture&) = delete;

 private:
  const GladGLContext& gl_;
  GLenum target_;
  GLint previous_ = 0;
};

// A new framebuffer bound to GL_READ_FRAMEBUFFER or GL_DRAW_FRAMEBUFFER for as long as this
// lives, with level `level` (layer `layer` of an array) of `texture` as colour attachment 0.
class AttachedFramebuffer {
 public:
  AttachedFramebuffer(const Context& context, GLenum binding, const GlObject& texture, int level, int layer)
      : gl_(context.gl()), binding_(binding), framebuffer_(context, GlKind::framebuffer) {
    gl_.GetIntegerv(binding == GL_READ_FRAMEBUFFER ? GL_READ_FRAMEBUFFER_BINDING : GL_DRAW_FRAMEBUFFER_BINDING,
                    &previous_);
    gl_.BindFramebuffer(binding_, framebuffer_.id());
    if (texture.target() == GL_TEXTURE_2D_ARRAY)
      gl_.FramebufferTextureLayer(binding_, GL_COLOR_ATTACHMENT0, texture.id(), level, layer);
    else
      gl_.FramebufferTexture2D(binding_, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.id(), level);
    const GLenum status = gl_.CheckFramebufferStatus(binding_);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      gl_.BindFramebuffer(binding_, static_cast<GLuint>(previous_));
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04X", status);
      throw Error(std::string("a framebuffer of the texture is incomplete (status ") + hex +
                      "): its format is not colour-renderable on this context",
                  ExitCode::failed);
    }
  }
  ~AttachedFramebuffer() { gl_.BindFramebuffer(binding_, static_cast<GLuint>(previous_)); }
  AttachedFramebuffer(const AttachedFramebuffer&) = delete;
  AttachedFramebuffer& operator=(const AttachedFramebuffer&) = delete;

 private:
  const GladGLContext& gl_;
  GLenum binding_;
  GlObject framebuffer_;
  GLint previous_ = 0;
};

void set_nearest_clamped(const GladGLContext& gl, const GlObject& texture, int levels) {
  const BoundTexture bound(gl, texture);
  const GLenum target = texture.target();
  gl.TexParameteri(target, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST);
  gl.TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

GLenum float_format(int channels) {
  static const GLenum formats[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
  if (channels < 1 || channels > 4) throw Error("texture channels " + std::to_string(channels) + ": expected 1 to 4");
  return formats[channels - 1];
}

int image_channels(const Context& context, int channels) { return context.is_es() && channels == 2 ? 4 : channels; }

GlObject make_texture(const Context& context, GLenum target, GLenum format, int width, int height, int layers,
                      int levels) {
  GlObject texture(context, GlKind::texture, target);
  const auto& gl = context.gl();
  {
    const BoundTexture bound(gl, texture);
    if (target == GL_TEXTURE_2D_ARRAY) gl.TexStorage3D(target, levels, format, width, height, layers);
    else gl.TexStorage2D(target, levels, format, width, height);
  }
  set_nearest_clamped(gl, texture, levels);
  return texture;
}

FloatTexture make_float_texture(const Context& context, int width, int height, int channels) {
  check_size(context, width, height);
  FloatTexture texture(make_texture(context, GL_TEXTURE_2D, float_format(channels), width, height), width, height,
                       channels);
  context.throw_if_gl_error("allocating a float texture");
  return texture;
}

GlObject make_float_texture_array(const Context& context, int width, int height, int layers, int channels) {
  check_size(context, width, height);
  GLint max_layers = 0;
  context.gl().GetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (layers < 1 || layers > max_layers)
    throw Error("texture array of " + std::to_string(layers) + " layers: expected 1 to GL_MAX_ARRAY_TEXTURE_LAYERS (" +
                std::to_string(max_layers) + ")");
  GlObject texture = make_texture(context, GL_TEXTURE_2D_ARRAY, float_format(channels), width, height, layers);
  context.throw_if_gl_error("allocating a float texture array");
  return texture;
}

GlObject make_texture_view_layer(const Context& context, const GlObject& array, int layer, int channels) {
  if (!context.has_texture_views())
    throw Error("texture views: this context has none (ES: GL_OES_texture_view or GL_EXT_texture_view)",
                ExitCode::failed);
  GlObject view(context, GlKind::texture, GL_TEXTURE_2D);
  const auto& gl = context.gl();
  gl.TextureView(view.id(), GL_TEXTURE_2D, array.id(), float_format(channels), 0, 1, static_cast<GLuint>(layer), 1);
  set_nearest_clamped(gl, view, 1);
  context.throw_if_gl_error("making a 2-D view of layer " + std::to_string(layer) + " of an array texture");
  return view;
}

GlObject copy_texture_layer(const Context& context, const GlObject& array, int layer, int width, int height,
                            int channels) {
  GlObject copy = make_float_texture(context, width, height, channels);
  const auto& gl = context.gl();
  gl.MemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);  // earlier image stores to the layer
  {
    const AttachedFramebuffer from(context, GL_READ_FRAMEBUFFER, array, 0, layer);
    const AttachedFramebuffer to(context, GL_DRAW_FRAMEBUFFER, copy, 0, 0);
    gl.BlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  context.throw_if_gl_error("copying layer " + std::to_string(layer) + " of an array texture");
  return copy;
}

GlObject texture_of_layer(const Context& context, const GlObject& array, int layer, int width, int height,
                          int channels) {
  if (context.has_texture_views()) return make_texture_view_layer(context, array, layer, channels);
  return copy_texture_layer(context, array, layer, width, height, channels);
}

FloatTexture upload_float_texture(const Context& context, const Image& image) {
  FloatTexture texture = make_float_texture(context, image.width, image.height, image.channels);
  const auto& gl = context.gl();
  {
    const BoundTexture bound(gl, texture);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, pixel_format(image.channels), GL_FLOAT,
                     image.texels.data());
  }
  context.throw_if_gl_error("uploading a float texture");
  return texture;
}

GlObject make_placeholder_texture(const Context& context, GLenum target, GLenum format) {
  return make_texture(context, target, format, 1, 1);
}

void clear_float_texture(const Context& context, const GlObject& texture, const float value[4]) {
  clear_texture_layer(context, texture, 0, 0, false, value);
}

void clear_texture_layer(const Context& context, const GlObject& texture, int level, int layer, bool integer,
                         const float value[4]) {
  {
    const AttachedFramebuffer target(context, GL_DRAW_FRAMEBUFFER, texture, level, layer);
    if (integer) {
      const GLuint words[4] = {static_cast<GLuint>(value[0]), static_cast<GLuint>(value[1]),
                               static_cast<GLuint>(value[2]), static_cast<GLuint>(value[3])};
      context.gl().ClearBufferuiv(GL_COLOR, 0, words);
    } else {
      context.gl().ClearBufferfv(GL_COLOR, 0, value);
    }
  }
  context.throw_if_gl_error("clearing a texture");
}

Image read_float_texture(const Context& context, const FloatTexture& texture) {
  return read_float_texture(context, texture, texture.width, texture.height, texture.channels);
}

Image read_float_texture(const Context& context, const GlObject& texture, int width, int height, int channels) {
  return read_float_texture_layer(context, texture, 0, width, height, channels);
}

void read_texels_via_framebuffer(const Context& context, const GlObject& texture, int level, int layer, int width,
                                 int height, bool integer, void* rgba) {
  const auto& gl = context.gl();
  gl.MemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  {
    const AttachedFramebuffer source(context, GL_READ_FRAMEBUFFER, texture, level, layer);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);  // 16-byte texels: rows are always aligned
    gl.ReadPixels(0, 0, width, height, integer ? GL_RGBA_INTEGER : GL_RGBA, integer ? GL_UNSIGNED_INT : GL_FLOAT, rgba);
  }
  context.throw_if_gl_error("reading back a texture through a framebuffer");
}

Image read_float_texture_layer(const Context& context, const GlObject& texture, int layer, int width, int height,
                               int channels, int level) {
  Image image(width, height, channels);
  const auto& gl = context.gl();
  if (context.is_es()) {
    std::vector<float> rgba(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
    read_texels_via_framebuffer(context, texture, level, layer, width, height, false, rgba.data());
    for (size_t i = 0; i < rgba.size() / 4; ++i)
      for (int c = 0; c < channels; ++c) image.texels[i * static_cast<size_t>(channels) + c] = rgba[i * 4 + c];
    return image;
  }
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  gl.GetTextureSubImage(texture.id(), level, 0, 0, layer, width, height, 1, pixel_format(channels), GL_FLOAT,
                        static_cast<GLsizei>(image.texels.size() * sizeof(float)), image.texels.data());
  context.throw_if_gl_error("reading back a float texture");
  return image;
}

std::vector<std::uint32_t> read_uint4_texture(const Context& context, const GlObject& texture, int width, int height) {
  std::vector<std::uint32_t> out(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  if (context.is_es()) {
    read_texels_via_framebuffer(context, texture, 0, 0, width, height, true, out.data());
    return out;
  }
  const auto& gl = context.gl();
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  gl.GetTextureSubImage(texture.id(), 0, 0, 0, 0, width, height, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                        static_cast<GLsizei>(out.size() * sizeof(std::uint32_t)), out.data());
  context.throw_if_gl_error("reading back an RGBA32UI texture");
  return out;
}

}  // namespace pn
