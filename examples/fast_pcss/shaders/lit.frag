// lit.frag — a forward lighting shader with Fast PCSS: Lambert from the area
// light's centre, times the soft-shadow visibility, plus ambient. The bundle
// of fast_pcss.glsl pasted before this file gives PnLight, pnLightProject,
// pnLightTexelWorld, pnFastPcss and pnFastPcssDefaults.

layout(binding = EX_LIT_MIP_BINDING) uniform sampler2D uMip;
layout(binding = EX_LIT_SAMPLE_TABLE_BINDING) uniform sampler2D uSampleTable;
layout(binding = EX_LIT_SHADOW_MAP_BINDING) uniform sampler2D uShadowMap;
layout(location = EX_LIGHT_VIEW_LOCATION) uniform mat4 uLightView;
#ifndef EX_LIGHT_PROJECTION_DECLARED  // mip_from_depth_buffer.glsl declares it at the same location
layout(location = EX_LIGHT_PROJECTION_LOCATION) uniform mat4 uLightProjection;
#endif
layout(location = EX_LIGHT_LOCATION) uniform PnLight uLight;
layout(location = EX_BIAS_LOCATION) uniform float uBias;
layout(location = EX_NORMAL_OFFSET_LOCATION) uniform float uNormalOffsetTexels;
layout(location = EX_CAMERA_POSITION_LOCATION) uniform vec3 uCameraPosition;
layout(location = EX_LIGHT_POSITION_LOCATION) uniform vec3 uLightPosition;
layout(location = EX_ALBEDO_LOCATION) uniform vec3 uAlbedo;
layout(location = EX_AMBIENT_LOCATION) uniform float uAmbient;

in vec3 vWorld;
layout(location = EX_LIT_COLOUR_OUTPUT) out vec4 outColour;
layout(location = EX_LIT_VISIBILITY_OUTPUT) out float outVisibility;

void main() {
  // The face normal from the screen-space derivatives (no normal attribute), turned toward the camera.
  vec3 normal = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
  if (dot(normal, uCameraPosition - vWorld) < 0.0) normal = -normal;

  // ---- Fast PCSS: what an engine adds to its lighting shader ----
  // The receiver in the shadow map's terms: (u, v) in texels and linear light depth, taken
  // from the point moved uNormalOffsetTexels shadow-map texels off its face.
  float lightDepth = -(uLightView * vec4(vWorld, 1.0)).z;
  vec3 offsetWorld = vWorld + normal * (uNormalOffsetTexels * pnLightTexelWorld(uLight, lightDepth));
  vec3 receiver = pnLightProject(uLightView, uLightProjection, uLight.mapSize, offsetWorld);
  // The screen pixel picks the sample table's set, so neighbouring pixels sample differently.
  float visibility = pnFastPcss(uShadowMap, uMip, uSampleTable, uLight, receiver, ivec2(gl_FragCoord.xy),
                                pnFastPcssDefaults(uBias));
  // ----------------------------------------------------------------

  vec3 toLight = uLightPosition - vWorld;
  float lambert = clamp(dot(normal, toLight) / length(toLight), 0.0, 1.0);
  outColour = vec4(uAlbedo * (uAmbient + (1.0 - uAmbient) * lambert * visibility), 1.0);
  outVisibility = visibility;
}
