// depth_cache.glsl — a shadow map kept as two depth maps (seed 001): one of
// the objects that stand still, one of those that move, composed per texel.
//
// description:
//   Seed 001 (Cao, Feng), SPEC §5. The static map holds the linear light
//   depth of the objects that did not move, the dynamic map that of the
//   objects that did; the shadow map of the whole scene is, texel by texel,
//     composed(p) = min(static(p), dynamic(p))
//   because the nearest surface of a set of objects is the nearer of the
//   nearest surfaces of its two parts. Non-finite depths (NaN, +Inf, -Inf)
//   mean "no occluder" (SPEC §3) and enter as +Inf before the min, so the
//   composition of two maps that both see nothing is +Inf, never NaN, and a
//   -Inf texel never shadows anything.
//   The shadow test is the seed's: a receiver at linear light depth dP is in
//   shadow when composed(p) < dP - bias (the occluder strictly in front of
//   it, as pcf.glsl's pnPcfOccludes), lit otherwise; a NaN receiver is lit.
//   Both maps must share the light's view, projection and size; the cache
//   that keeps them (runner/cache/) decides which texels to redraw.
//
// use:
//   float pnDepthCacheCompose(float staticDepth, float dynamicDepth)
//         min of the two, non-finite -> +Inf first
//   float pnDepthCacheComposeAt(sampler2D staticMap, sampler2D dynamicMap, ivec2 texel)
//         the composition at a texel (texel clamped into the maps: no read out of bounds)
//   float pnDepthCacheLit(float composedDepth, float receiverDepth, float bias)
//         1 lit, 0 in shadow
//   float pnDepthCacheVisibility(sampler2D staticMap, sampler2D dynamicMap, ivec2 texel,
//                                float receiverDepth, float bias)
//         the shadow test against the composition at a texel
//   float pnDepthCacheFar()   +Inf, "no occluder"
//   maps: linear light depth in .r (R32F or any float format), one level,
//   texelFetch only.
//
// cost: two fetches, a min and a compare per texel; the memory of two maps
//   (plus the composed map when a pass keeps it: 3 · 4 · N² bytes in R32F).

#ifndef PENUMBRA_DEPTH_CACHE_GLSL
#define PENUMBRA_DEPTH_CACHE_GLSL

float pnDepthCacheFar() {
  return uintBitsToFloat(0x7f800000u);
}

float pn_depthCacheSanitize(float d) {
  return (isnan(d) || isinf(d)) ? pnDepthCacheFar() : d;
}

float pnDepthCacheCompose(float staticDepth, float dynamicDepth) {
  return min(pn_depthCacheSanitize(staticDepth), pn_depthCacheSanitize(dynamicDepth));
}

float pnDepthCacheComposeAt(sampler2D staticMap, sampler2D dynamicMap, ivec2 texel) {
  ivec2 last = min(textureSize(staticMap, 0), textureSize(dynamicMap, 0)) - ivec2(1);
  ivec2 p = clamp(texel, ivec2(0), last);
  return pnDepthCacheCompose(texelFetch(staticMap, p, 0).r, texelFetch(dynamicMap, p, 0).r);
}

float pnDepthCacheLit(float composedDepth, float receiverDepth, float bias) {
  // A NaN threshold compares false: lit. composedDepth is finite or +Inf here.
  return (composedDepth < receiverDepth - bias) ? 0.0 : 1.0;
}

float pnDepthCacheVisibility(sampler2D staticMap, sampler2D dynamicMap, ivec2 texel, float receiverDepth,
                             float bias) {
  return pnDepthCacheLit(pnDepthCacheComposeAt(staticMap, dynamicMap, texel), receiverDepth, bias);
}

#endif  // PENUMBRA_DEPTH_CACHE_GLSL
