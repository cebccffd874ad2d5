// mip_from_depth_buffer.glsl — pasted BEFORE the bundle in mip_build.comp and
// lit.frag when the shadow map is the light's hardware depth buffer
// (--depth-buffer): minmax_mip.glsl's option PN_MIP_LEVEL0_DEPTH turns each
// texel into linear light depth as the chain is built and wherever Fast PCSS
// reads a texel of the map, so the engine makes no linear copy. The macro is
// expanded inside the bundle, after light_model.glsl has defined
// pnLightDepthFromDepthBuffer; false: OpenGL's default [-1, 1] clip range.
// (Both programs hold the light's projection at location 1: lit.frag leaves
// its own declaration out when this file declared it.)

layout(location = EX_MIP_LIGHT_PROJECTION_LOCATION) uniform mat4 uLightProjection;
#define EX_LIGHT_PROJECTION_DECLARED
#define PN_MIP_LEVEL0_DEPTH(value) pnLightDepthFromDepthBuffer(uLightProjection, value, false)
