#version 450
// shade.comp — the shading pass, the GLSL route: Fast PCSS from the bundle of fast_pcss.glsl, once a
// pixel of the G-buffer, then Lambert from the area light's centre times the visibility, plus
// ambient. shade.hlsl is the same pass through the HLSL export.
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
#include "fast_pcss_bundle.glsl"  // generated: penumbra_bundle(... MODULE fast_pcss.glsl BARE)
#include "light.glsl"
layout(local_size_x = EX_SHADE_GROUP_SIZE, local_size_y = EX_SHADE_GROUP_SIZE) in;
layout(binding = EX_SHADE_RECEIVERS) uniform sampler2D uReceivers;
layout(binding = EX_SHADE_WORLD) uniform sampler2D uWorld;
layout(binding = EX_SHADE_NORMAL) uniform sampler2D uNormal;
layout(binding = EX_SHADE_SHADOW_MAP) uniform sampler2D uShadowMap;
layout(binding = EX_SHADE_MIP) uniform sampler2D uMip;
layout(binding = EX_SHADE_SAMPLE_TABLE) uniform sampler2D uSampleTable;
layout(r32f, binding = EX_SHADE_VISIBILITY) writeonly uniform image2D uVisibility;
layout(rgba32f, binding = EX_SHADE_LIT) writeonly uniform image2D uLit;
void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(uLit)))) return;
  vec4 receiver = texelFetch(uReceivers, pixel, 0);
  if (receiver.w == 0.0) {  // nothing drawn: the sky, lit
    imageStore(uLit, pixel, vec4(exSky.rgb, 1.0));
    imageStore(uVisibility, pixel, vec4(1.0));
    return;
  }
  // ---- Fast PCSS: what an engine adds to its lighting pass ----
  // The pixel picks the sample table's set, so neighbouring pixels sample differently.
  float visibility = pnFastPcss(uShadowMap, uMip, uSampleTable, exPnLight(), receiver.xyz, pixel,
                                pnFastPcssDefaults(exLight1.z));
  // --------------------------------------------------------------
  vec4 world = texelFetch(uWorld, pixel, 0);
  vec3 normal = texelFetch(uNormal, pixel, 0).xyz;
  vec3 toLight = exLightPosition.xyz - world.xyz;
  float lambert = clamp(dot(normal, toLight) / length(toLight), 0.0, 1.0);
  vec3 albedo = world.w == 0.0 ? exGroundAlbedo.rgb : exModelAlbedo.rgb;
  imageStore(uLit, pixel, vec4(albedo * (exShading.x + (1.0 - exShading.x) * lambert * visibility), 1.0));
  imageStore(uVisibility, pixel, vec4(visibility));
}
