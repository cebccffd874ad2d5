// exports/savsm.comp — the entry `penumbra bundle savsm.glsl --target hlsl|msl` translates
// (runner/shader/export_source.h). SPIR-V keeps only what an entry point reaches, so this entry
// calls pnSavsm once per receiver of a receiver image: the export then holds the call and
// everything it calls, with the parameters' names. Its bindings are an example; an engine calls
// the exported function from its own shader with its own resources.

layout(local_size_x = 8, local_size_y = 8) in;

#include "savsm.glsl"

layout(rgba32f, binding = 0) writeonly uniform image2D pnVisibility;
layout(binding = 1) uniform sampler2D pnReceivers;       // (u, v, light depth, 0)
layout(binding = 3) uniform PN_SAVSM_TABLE_SAMPLER pnTable;  // the moments' summed-area table (summed_area.glsl)
layout(binding = 4) uniform sampler2D pnMip;                   // the aligned min/max mip chain (the bound)
layout(std140, binding = 5) uniform PnSavsmExport {
  PnLight light;
  PnSavsmSettings settings;
  vec2 unitRange;  // the table's depth range
} pnExport;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 r = texelFetch(pnReceivers, p, 0);
  float v = pnSavsm(pnTable, pnMip, pnExport.light, r.xyz, pnExport.unitRange, pnExport.settings);
  imageStore(pnVisibility, p, vec4(v));
}
