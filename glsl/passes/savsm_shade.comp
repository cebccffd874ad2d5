// savsm_shade.comp — the savsm technique's visibility: per screen pixel, its
// G-buffer entry (u, v in shadow-map texels, light depth, valid) through
// savsm.glsl against the moments table and the min/max mip chain. A pixel that
// sees no surface is lit.
//   bindings and parameter block: savsm_params.h
//
// options:
//   PN_SAVSM_TABLE   PN_SAVSM_TABLE_FIXED (default) or _FLOAT: the table's
//   kind and sampler type; the runner compiles one program per kind.

layout(local_size_x = 8, local_size_y = 8) in;

#include "savsm_params.h"
#include "savsm.glsl"

layout(binding = PN_SAVSM_TABLE_BINDING) uniform PN_SAVSM_TABLE_SAMPLER pnTable;
layout(binding = PN_SAVSM_MIP_BINDING) uniform sampler2D pnMip;
layout(binding = PN_SAVSM_INPUT_BINDING) uniform sampler2D pnGBuffer;
layout(r32f, binding = PN_SAVSM_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;

#include "savsm_params.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 g = texelFetch(pnGBuffer, p, 0);
  float v = 1.0;
  if (g.w != 0.0) {
    v = pnSavsm(pnTable, pnMip, pnSavsmParamsLight(), g.xyz, pnParams.unitRange, pnSavsmParamsSettings());
  }
  imageStore(pnVisibility, p, vec4(v, 0.0, 0.0, 0.0));
}
