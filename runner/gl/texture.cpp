#include "gl/texture.h"

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

void set_nearest_clamped(const GladGLContext& gl, GLuint texture) {
  gl.TextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

GLenum float_format(int channels) {
  static const GLenum formats[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
  if (channels < 1 || channels > 4) throw Error("texture channels " + std::to_string(channels) + ": expected 1 to 4");
  return formats[channels - 1];
}

GlObject make_float_texture(const Context& context, int width, int height, int channels) {
  check_size(context, width, height);
  GlObject texture(context, GlKind::texture, GL_TEXTURE_2D);
  context.gl().TextureStorage2D(texture.id(), 1, float_format(channels), width, height);
  set_nearest_clamped(context.gl(), texture.id());
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
  GlObject texture(context, GlKind::texture, GL_TEXTURE_2D_ARRAY);
  context.gl().TextureStorage3D(texture.id(), 1, float_format(channels), width, height, layers);
  set_nearest_clamped(context.gl(), texture.id());
  context.throw_if_gl_error("allocating a float texture array");
  return texture;
}

GlObject make_texture_view_layer(const Context& context, const GlObject& array, int layer, int channels) {
  GlObject view(context, GlKind::texture_view);
  const auto& gl = context.gl();
  gl.TextureView(view.id(), GL_TEXTURE_2D, array.id(), float_format(channels), 0, 1, static_cast<GLuint>(layer), 1);
  set_nearest_clamped(gl, view.id());
  context.throw_if_gl_error("making a 2-D view of layer " + std::to_string(layer) + " of an array texture");
  return view;
}

GlObject upload_float_texture(const Context& context, const Image& image) {
  GlObject texture = make_float_texture(context, image.width, image.height, image.channels);
  const auto& gl = context.gl();
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, pixel_format(image.channels), GL_FLOAT,
                       image.texels.data());
  context.throw_if_gl_error("uploading a float texture");
  return texture;
}

GlObject make_placeholder_texture(const Context& context, GLenum target, GLenum format) {
  GlObject t(context, GlKind::texture, target);
  if (target == GL_TEXTURE_2D_ARRAY) context.gl().TextureStorage3D(t.id(), 1, format, 1, 1, 1);
  else context.gl().TextureStorage2D(t.id(), 1, format, 1, 1);
  return t;
}

Image read_float_texture(const Context& context, const GlObject& texture, int width, int height, int channels) {
  return read_float_texture_layer(context, texture, 0, width, height, channels);
}

Image read_float_texture_layer(const Context& context, const GlObject& texture, int layer, int width, int height,
                               int channels) {
  Image image(width, height, channels);
  const auto& gl = context.gl();
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  gl.GetTextureSubImage(texture.id(), 0, 0, 0, layer, width, height, 1, pixel_format(channels), GL_FLOAT,
                        static_cast<GLsizei>(image.texels.size() * sizeof(float)), image.texels.data());
  context.throw_if_gl_error("reading back a float texture");
  return image;
}

}  // namespace pn
