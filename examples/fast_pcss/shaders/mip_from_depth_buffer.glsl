// mip_from_depth_buffer.glsl — pasted BEFORE the bundle in mip_build.comp when
// the shadow map is the light's hardware depth buffer (--depth-buffer):
// minmax_mip.glsl's option PN_MIP_LEVEL0_DEPTH turns each texel into linear
// light depth as level 0 is built, so the engine makes no linear copy. The
// macro is expanded inside the bundle, after light_model.glsl has defined
// pnLightDepthFromDepthBuffer; false: OpenGL's default [-1, 1] clip range.

layout(location = EX_MIP_LIGHT_PROJECTION_LOCATION) uniform mat4 uLightProjection;
#define PN_MIP_LEVEL0_DEPTH(value) pnLightDepthFromDepthBuffer(uLightProjection, value, false)
