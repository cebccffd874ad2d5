#!/bin/sh
# bundle_in_fragment.sh PENUMBRA GLSLANG_VALIDATOR OUT_DIR GLSL_DIR
# Each technique's one call as an engine takes it: `penumbra bundle MODULE --bare`
# pasted after an engine's own fragment-shader header (its #version, precisions
# on ES, its samplers and options), then a main that calls the technique and
# writes the visibility; Debian's glslangValidator must compile it as a
# fragment shader for GL 4.50, Vulkan (SPIR-V) and GLSL ES 3.10.
set -u
penumbra=$1 validator=$2 out=$3 glsl=$4
rm -rf "$out" && mkdir -p "$out" || exit 1
status=0

# module | declarations before the bundle | the call (receiver r, light L: a macro, expanded only where used)
calls='fast_pcss.glsl|S(0) uniform sampler2D uMap; S(1) uniform sampler2D uMip; S(2) uniform sampler2D uTable;|pnFastPcss(uMap, uMip, uTable, L, r, ivec2(gl_FragCoord.xy), pnFastPcssDefaults(0.02))
poisson_pcss.glsl|S(0) uniform sampler2D uMap; const vec2 B[2] = vec2[](vec2(0.1, 0.2), vec2(-0.3, 0.4)); const vec2 F[3] = vec2[](vec2(0.5, 0.0), vec2(0.0, -0.5), vec2(-0.2, 0.1));\n#define PN_POISSON_BLOCKER_DISK B\n#define PN_POISSON_FILTER_DISK F|pnPoissonPcss(uMap, L, r, pnPoissonPcssDefaults(0.02), pnPoissonRotation(gl_FragCoord.x))
vogel_pcss.glsl|S(0) uniform sampler2D uMap;|pnVogelPcss(uMap, L, r, ivec2(gl_FragCoord.xy), pnVogelPcssDefaults(0.02)) * pnVogelPcss(uMap, L, r, pnReceiverPlaneGradient(dFdx(r), dFdy(r), 0.1), ivec2(gl_FragCoord.xy), pnVogelPcssDefaults(0.02))
exact_pcss.glsl|S(0) uniform sampler2D uMap;|pnExactPcss(uMap, L, r, 0.02, 1.0)
hqepcss.glsl|S(0) uniform sampler2DArray uPyramid; S(1) uniform sampler2D uMap;|pnHqepcss(uPyramid, uMap, L, r, pnHqepcssDefaults(0.02))
pcf.glsl|S(0) uniform sampler2D uMap;|pnPcf(uMap, r, 0.02)
vsm.glsl|S(0) uniform sampler2D uMoments; S(1) uniform sampler2DArray uPyramid;|pnVsm(uMoments, uPyramid, r, 3, 0.02, 1e-4, 0.2) * pnEvsm2(uMoments, uPyramid, r, 3, 0.02, vec2(1.0, 100.0), 40.0, 1e-4, 0.2) * pnEvsm4(uMoments, uPyramid, r, 3, 0.02, vec2(1.0, 100.0), vec2(40.0, 5.0), 1e-4, 0.2)
savsm.glsl|S(0) uniform usampler2D uTable; S(1) uniform sampler2D uMip;|pnSavsm(uTable, uMip, L, r, vec2(1.0, 0.01), PnSavsmSettings(0.02, 1.0, 1e-4, 0.2, PN_SAVSM_BLOCKER_MIN, true))'

printf '%s\n' "$calls" | while IFS='|' read -r module declarations call; do
  bundle="$out/$(basename "$module" .glsl).bundle.glsl"
  "$penumbra" bundle "$glsl/$module" --bare --glsl-root "$glsl" -o "$bundle" || { echo "bundle $module --bare failed"; exit 1; }
  for target in gl450 vulkan es310; do
    file="$out/$(basename "$module" .glsl).$target.frag"
    case $target in
      gl450) printf '#version 450 core\n#define S(b) layout(binding = b)\n' ;;
      vulkan) printf '#version 450\n#define S(b) layout(set = 0, binding = b)\n' ;;
      es310) printf '#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\nprecision highp usampler2D;\nprecision highp sampler2DArray;\n#define S(b) layout(binding = b)\n' ;;
    esac > "$file"
    printf '%b\n' "$declarations" >> "$file"
    cat "$bundle" >> "$file"
    cat >> "$file" <<GLSL
#define L PnLight(2.0, 1.0, 2.0, 1024.0, 0.0, 0.0)
layout(location = 0) in vec3 vReceiver;
layout(location = 0) out vec4 outColour;
void main() {
  vec3 r = vReceiver;
  outColour = vec4($call);
}
GLSL
    flag=""; [ "$target" = vulkan ] && flag="-V -o $out/spv"
    "$validator" $flag "$file" > "$file.log" 2>&1 || { cat "$file.log"; echo "glslangValidator rejected $file"; exit 1; }
  done
  echo "$module: the call compiles in a fragment shader for gl450, vulkan, es310"
done || status=1

# The #include route without an include processor (integration.md): glslangValidator -E expands the
# includes; its GL output keeps GL_GOOGLE_include_directive and named #line directives, which a GL
# driver refuses, so they go; what is left compiles as GLSL 4.50 with no include support.
src="$out/include_route.frag"
cat > "$src" <<'GLSL'
#version 450 core
#extension GL_GOOGLE_include_directive : require
layout(binding = 0) uniform sampler2D uMap;
layout(binding = 1) uniform sampler2D uMip;
layout(binding = 2) uniform sampler2D uTable;
#include "fast_pcss.glsl"
layout(location = 0) in vec3 vReceiver;
layout(location = 0) out vec4 outColour;
void main() {
  PnLight light = PnLight(2.0, 1.0, 2.0, 1024.0, 0.0, 0.0);
  outColour = vec4(pnFastPcss(uMap, uMip, uTable, light, vReceiver, ivec2(gl_FragCoord.xy), pnFastPcssDefaults(0.02)));
}
GLSL
"$validator" -S frag "$src" > "$out/plain.log" 2>&1 && { echo "glslangValidator without -E accepted #include"; status=1; }
"$validator" -E -S frag -I"$glsl" "$src" > "$out/expanded.frag" 2> "$out/expanded.log" || {
  cat "$out/expanded.log"; echo "glslangValidator -E could not expand the includes"; status=1; }
grep -v -e '^#extension GL_GOOGLE_include_directive' -e '^#line ' "$out/expanded.frag" > "$out/for_gl.frag"
if grep -q '#include' "$out/for_gl.frag"; then echo "an #include is left after -E"; status=1; fi
"$validator" -S frag "$out/for_gl.frag" > "$out/for_gl.log" 2>&1 || { cat "$out/for_gl.log"; echo "the expanded text does not compile"; status=1; }
[ $status -eq 0 ] && echo "the #include route: glslangValidator -E, then GLSL 4.50 without includes"
exit $status
