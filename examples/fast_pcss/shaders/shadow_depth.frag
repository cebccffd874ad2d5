// shadow_depth.frag — writes the linear light depth into the R32F target.
// It is linear in view space, so the perspective-correct interpolation gives
// each texel the depth of the surface point through its centre. (Converting
// a D32F depth buffer back to linear depth would do too; the module only
// needs linear depth, +Inf where nothing was drawn.)

in float vLightDepth;
layout(location = 0) out float outLightDepth;

void main() {
  outLightDepth = vLightDepth;
}
