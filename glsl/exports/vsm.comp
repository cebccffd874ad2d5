// exports/vsm.comp — the entry `penumbra bundle vsm.glsl --target hlsl|msl` translates
// (runner/shader/export_source.h). SPIR-V keeps only what an entry point reaches, so this entry
// calls pnVsm, pnEvsm2 and pnEvsm4 once per receiver of a receiver image: the export then holds
// the calls and everything they call, with the parameters' names. Its bindings are an example; an
// engine calls the exported function from its own shader with its own resources.

layout(local_size_x = 8, local_size_y = 8) in;

#include "vsm.glsl"

layout(rgba32f, binding = 0) writeonly uniform image2D pnVisibility;
layout(binding = 1) uniform sampler2D pnReceivers;       // (u, v, light depth, 0)
layout(binding = 3) uniform sampler2D pnMoments;       // the blurred moments (vsm.glsl)
layout(binding = 4) uniform sampler2DArray pnPyramid;  // the depth pyramid's first levels (the bound)
layout(std140, binding = 5) uniform PnVsmExport {
  vec4 exponents;  // (EVSM2's exponent, EVSM4's two, 0)
  vec2 depthRange;
  float bias;
  float minVariance;
  float bleedingReduction;
  int radius;
  int kind;  // 0 VSM, 1 EVSM2, 2 EVSM4
} pnExport;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  vec4 r = texelFetch(pnReceivers, p, 0);
  float v = pnExport.kind == 0
                ? pnVsm(pnMoments, pnPyramid, r.xyz, pnExport.radius, pnExport.bias, pnExport.minVariance,
                        pnExport.bleedingReduction)
            : pnExport.kind == 1
                ? pnEvsm2(pnMoments, pnPyramid, r.xyz, pnExport.radius, pnExport.bias, pnExport.depthRange,
                          pnExport.exponents.x, pnExport.minVariance, pnExport.bleedingReduction)
                : pnEvsm4(pnMoments, pnPyramid, r.xyz, pnExport.radius, pnExport.bias, pnExport.depthRange,
                          pnExport.exponents.yz, pnExport.minVariance, pnExport.bleedingReduction);
  imageStore(pnVisibility, p, vec4(v));
}
