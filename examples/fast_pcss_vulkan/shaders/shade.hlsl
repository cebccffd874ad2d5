// shade.hlsl — the shading pass, the HLSL route: Fast PCSS from the HLSL export of fast_pcss.glsl
// (penumbra_bundle(... TARGET hlsl SHADER_MODEL 5.1 REGISTER_SPACE 1): the export's own example
// entry and its resources sit in space 1, out of this shader's way), called from this shader's own
// entry `shade` with this shader's own registers (vulkan_interface.h). The same pass as shade.comp.
#include "vulkan_interface.h"
#include "fast_pcss_export.hlsl"  // generated: pnFastPcss, pnFastPcssDefaults, PnLight

#define EX_HLSL_MAT4(NAME) float4x4 NAME;
#define EX_HLSL_VEC4(NAME) float4 NAME;
#define EX_REGISTER(KIND, N) EX_REGISTER_(KIND, N)
#define EX_REGISTER_(KIND, N) register(KIND##N)
cbuffer ExFrame : EX_REGISTER(b, EX_FRAME_BINDING) { EX_FRAME_MEMBERS(EX_HLSL_MAT4, EX_HLSL_VEC4) };

Texture2D<float4> exReceivers : EX_REGISTER(t, EX_SHADE_RECEIVERS);
Texture2D<float4> exWorld : EX_REGISTER(t, EX_SHADE_WORLD);
Texture2D<float4> exNormal : EX_REGISTER(t, EX_SHADE_NORMAL);
Texture2D<float4> exShadowMap : EX_REGISTER(t, EX_SHADE_SHADOW_MAP);
Texture2D<float4> exMip : EX_REGISTER(t, EX_SHADE_MIP);
Texture2D<float4> exSampleTable : EX_REGISTER(t, EX_SHADE_SAMPLE_TABLE);
RWTexture2D<float> exVisibility : EX_REGISTER(u, EX_SHADE_VISIBILITY);
RWTexture2D<float4> exLit : EX_REGISTER(u, EX_SHADE_LIT);
SamplerState exPointClamp : EX_REGISTER(s, EX_SHADE_SAMPLER);  // any sampler: the modules only Load

[numthreads(EX_SHADE_GROUP_SIZE, EX_SHADE_GROUP_SIZE, 1)]
void shade(uint3 id : SV_DispatchThreadID) {
  int2 pixel = int2(id.xy);
  uint width, height;
  exLit.GetDimensions(width, height);
  if (id.x >= width || id.y >= height) return;
  float4 receiver = exReceivers.Load(int3(pixel, 0));
  if (receiver.w == 0.0f) {  // nothing drawn: the sky, lit
    exLit[pixel] = float4(exSky.rgb, 1.0f);
    exVisibility[pixel] = 1.0f;
    return;
  }
  PnLight light;
  light.width = exLight0.x, light.near = exLight0.y, light.nearPlaneWidth = exLight0.z, light.mapSize = exLight0.w;
  light.spread = exLight1.x, light.texelWorld = exLight1.y;
  // ---- Fast PCSS: what an engine adds to its lighting pass ----
  float visibility = pnFastPcss(exShadowMap, exPointClamp, exMip, exPointClamp, exSampleTable, exPointClamp, light,
                                receiver.xyz, pixel, pnFastPcssDefaults(exLight1.z));
  // --------------------------------------------------------------
  float4 world = exWorld.Load(int3(pixel, 0));
  float3 normal = exNormal.Load(int3(pixel, 0)).xyz;
  float3 toLight = exLightPosition.xyz - world.xyz;
  float lambert = clamp(dot(normal, toLight) / length(toLight), 0.0f, 1.0f);
  float3 albedo = world.w == 0.0f ? exGroundAlbedo.rgb : exModelAlbedo.rgb;
  exLit[pixel] = float4(albedo * (exShading.x + (1.0f - exShading.x) * lambert * visibility), 1.0f);
  exVisibility[pixel] = visibility;
}
