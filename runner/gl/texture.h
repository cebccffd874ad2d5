// Float textures for passes: upload an Image unchanged (no 8-bit quantisation),
// allocate a target, read a result back as floats.
#pragma once

#include "core/image.h"
#include "gl/objects.h"

namespace pn {

// Immutable-storage 2-D texture of 1–4 float channels (R32F … RGBA32F), nearest filtering.
GlObject make_float_texture(const Context& context, int width, int height, int channels);

// A 1×1 (×1 layer) texture of `format` for GL_TEXTURE_2D or GL_TEXTURE_2D_ARRAY: bound where a
// pass declares a sampler that this dispatch does not read.
GlObject make_placeholder_texture(const Context& context, GLenum target, GLenum format);
GlObject upload_float_texture(const Context& context, const Image& image);
Image read_float_texture(const Context& context, const GlObject& texture, int width, int height, int channels);

// Immutable-storage 2-D array texture, `layers` layers of width × height floats.
GlObject make_float_texture_array(const Context& context, int width, int height, int layers, int channels);
// A GL_TEXTURE_2D view (glTextureView) of one layer of an immutable-storage array texture:
// same texels, no copy, `channels` floats per texel (the array's format), nearest filtering.
GlObject make_texture_view_layer(const Context& context, const GlObject& array, int layer, int channels);
// The top-left width × height texels of one layer of an array texture (layer 0 of a 2-D one).
Image read_float_texture_layer(const Context& context, const GlObject& texture, int layer, int width, int height,
                               int channels);

// GL internal format for `channels` floats (GL_R32F … GL_RGBA32F).
GLenum float_format(int channels);

}  // namespace pn
