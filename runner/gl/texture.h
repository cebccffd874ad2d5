// Float textures for passes: upload an Image unchanged (no 8-bit quantisation),
// allocate a target, read a result back as floats.
//
// One code path for GL 4.5 core and OpenGL ES 3.1: immutable storage (glTexStorage*) edited
// bound (bind-to-edit), and one named fallback for each feature only desktop GL has:
// - readback: glGetTextureSubImage on GL 4.5; on ES (no glGetTexImage) glReadPixels of the level
//   and layer attached to a framebuffer, as RGBA floats (or RGBA uints), which is exact — every
//   texture the runner reads back is R32F, RG32F, RGBA32F (colour-renderable with
//   GL_EXT_color_buffer_float, which an ES context must have) or RGBA32UI (read_texels_via_framebuffer);
// - views: glTextureView (GL 4.3; ES: glTextureViewOES/EXT), else a copy of the layer (copy_texture_layer);
// - clears: through a framebuffer (glClearBufferfv) on both APIs, instead of GL 4.4's glClearTexImage.
// RGB32F (3 channels) is neither colour-renderable nor an image format on ES: it may be uploaded
// and sampled, never rendered into, written as an image or read back there.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/image.h"
#include "gl/objects.h"

namespace pn {

// Immutable storage (glTexStorage2D/3D) of `levels` levels of `format` for GL_TEXTURE_2D
// (`layers` = 1) or GL_TEXTURE_2D_ARRAY, nearest filtering (nearest mip with more than one
// level), clamped to the edge. No size checks: the callers state their own limits.
GlObject make_texture(const Context& context, GLenum target, GLenum format, int width, int height, int layers = 1,
                      int levels = 1);

// A 2-D float texture that knows its size and channels, so a readback need not restate them. It is
// a GlObject, so whatever binds or reads any texture takes it as one.
struct FloatTexture : GlObject {
  FloatTexture() = default;
  FloatTexture(GlObject object, int width, int height, int channels)
      : GlObject(std::move(object)), width(width), height(height), channels(channels) {}
  int width = 0, height = 0, channels = 0;
};

// Immutable-storage 2-D texture of 1–4 float channels (R32F … RGBA32F), nearest filtering.
FloatTexture make_float_texture(const Context& context, int width, int height, int channels);

// A 1×1 (×1 layer) texture of `format` for GL_TEXTURE_2D or GL_TEXTURE_2D_ARRAY: bound where a
// pass declares a sampler that this dispatch does not read.
GlObject make_placeholder_texture(const Context& context, GLenum target, GLenum format);
FloatTexture upload_float_texture(const Context& context, const Image& image);
// Level 0 of the whole texture (the second form for a texture kept as a plain GlObject).
Image read_float_texture(const Context& context, const FloatTexture& texture);
Image read_float_texture(const Context& context, const GlObject& texture, int width, int height, int channels);

// Sets every texel of level 0 of a 2-D float texture (R32F, RG32F, RGBA32F) to `value` (its
// first channels), through a framebuffer.
void clear_float_texture(const Context& context, const GlObject& texture, const float value[4]);
// Level `level`, layer `layer` (of a 2-D array; 0 otherwise) of a float or (`integer`) RGBA32UI
// texture set to `value` (whole numbers for RGBA32UI), through a framebuffer.
void clear_texture_layer(const Context& context, const GlObject& texture, int level, int layer, bool integer,
                         const float value[4]);

// Immutable-storage 2-D array texture, `layers` layers of width × height floats.
GlObject make_float_texture_array(const Context& context, int width, int height, int layers, int channels);
// A GL_TEXTURE_2D view (glTextureView) of one layer of an immutable-storage array texture:
// same texels, no copy, `channels` floats per texel (the array's format), nearest filtering.
// Throws Error where the context has no texture views (Context::has_texture_views).
GlObject make_texture_view_layer(const Context& context, const GlObject& array, int layer, int channels);
// The fallback for contexts without views: a new 2-D texture holding a copy of the layer as it
// is now (glBlitFramebuffer, nearest, same size and format: exact). Float formats only.
GlObject copy_texture_layer(const Context& context, const GlObject& array, int layer, int width, int height,
                            int channels);
// A 2-D texture of one layer: a view where the context has views, else a copy (taken now, so
// take it after the layer is written).
GlObject texture_of_layer(const Context& context, const GlObject& array, int layer, int width, int height,
                          int channels);
// The top-left width × height texels of one layer (layer 0 of a 2-D texture) of level `level`.
Image read_float_texture_layer(const Context& context, const GlObject& texture, int layer, int width, int height,
                               int channels, int level = 0);
// The top-left width × height texels of level 0 of an RGBA32UI texture, 4 uints a texel.
std::vector<std::uint32_t> read_uint4_texture(const Context& context, const GlObject& texture, int width, int height);

// ES's readback (used on GL 4.5 only by the tests that compare it with glGetTextureSubImage):
// level `level`, layer `layer` attached to a framebuffer and read with glReadPixels as 4 floats
// (GL_RGBA, GL_FLOAT) or, `integer`, 4 uints (GL_RGBA_INTEGER, GL_UNSIGNED_INT) a texel into `rgba`
// (width · height · 4 values).
void read_texels_via_framebuffer(const Context& context, const GlObject& texture, int level, int layer, int width,
                                 int height, bool integer, void* rgba);

// GL internal format for `channels` floats (GL_R32F … GL_RGBA32F).
GLenum float_format(int channels);

// The channels of the image a pass writes `channels` floats into: `channels` on GL 4.5; on ES,
// where RG32F is not an image format (ES 3.1 Table 8.27), 2 become 4 (RGBA32F; the passes'
// shaders pick rgba32f under GL_ES the same way).
int image_channels(const Context& context, int channels);

}  // namespace pn
