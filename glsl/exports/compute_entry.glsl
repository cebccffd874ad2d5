// exports/compute_entry.glsl — the compute stage of every export entry (exports/X.comp): one
// invocation a texel of the receiver image, the call's visibility (pnExportCall of
// exports/X_call.glsl, which defines PN_EXPORT_CALL) stored in the visibility image.
// Included after the call.

#ifdef PN_EXPORT_CALL
#include "exports.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(r32f, binding = PN_EXPORT_VISIBILITY_IMAGE) writeonly uniform image2D pnVisibility;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(pnVisibility)))) return;
  imageStore(pnVisibility, p, vec4(pnExportCall(p)));
}
#else  // alone (lint): an empty compute shader
layout(local_size_x = 1) in;
void main() {}
#endif
