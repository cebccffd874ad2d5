// shadow_depth.frag — writes the linear light depth into an R32F target.
// Linear in view space, it is interpolated perspective-correctly, so each
// texel holds the depth of the surface point through its centre.

layout(location = 0) in float pnLinearDepth;
layout(location = 0) out vec4 pnDepth;

void main() {
  pnDepth = vec4(pnLinearDepth, 0.0, 0.0, 0.0);
}
