#version 450
// shadow_depth.frag — the linear light depth into the R32F target (cleared to +Inf: no occluder).
layout(location = 0) in float vLightDepth;
layout(location = 0) out float outLightDepth;
void main() { outLightDepth = vLightDepth; }
