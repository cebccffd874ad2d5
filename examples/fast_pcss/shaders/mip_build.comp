// mip_build.comp — one level of the aligned min/max mip chain that Fast PCSS
// traverses (minmax_mip.glsl), one dispatch per level, its first (node level 2,
// 4×4 texels a node: the levels below are the map itself) first: that level
// from the shadow map, level i from level i - 1. uLevel is the node level, the
// image bound its mip (uLevel - 2). The bundle pasted before this file gives
// pnMipFirstTexel and pnMipCombineTexel; the chain is read (sampler, all
// levels) and written (image, this level) through one texture.

layout(local_size_x = EX_MIP_GROUP_SIZE, local_size_y = EX_MIP_GROUP_SIZE) in;

layout(binding = EX_MIP_SHADOW_MAP_BINDING) uniform sampler2D uShadowMap;
layout(binding = EX_MIP_READ_BINDING) uniform sampler2D uMipRead;
layout(rgba32f, binding = EX_MIP_WRITE_IMAGE) writeonly uniform image2D uMipWrite;
layout(location = EX_MIP_LEVEL_LOCATION) uniform int uLevel;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(uMipWrite)))) return;
  vec4 nodes = uLevel <= PN_MIP_FIRST_LEVEL ? pnMipFirstTexel(uShadowMap, texel)
                                            : pnMipCombineTexel(uMipRead, uLevel, texel);
  imageStore(uMipWrite, texel, nodes);
}
