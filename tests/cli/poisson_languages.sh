#!/bin/sh
# poisson_languages.sh PENUMBRA GLSLANG_VALIDATOR CXX OUT_DIR
# `penumbra poisson --lang` (issue 53): the 64-sample disk as GLSL, HLSL, MSL and C++. The GLSL
# compiles in a fragment shader for GL 4.50 and the HLSL through glslang's HLSL front end, each
# indexing the last point; the C++ compiles with the host compiler and its program prints every
# point; every language's points equal the GLSL's, value for value (MSL, which nothing here
# compiles, by its text).
set -u
penumbra=$1 validator=$2 cxx=$3 out=$4
rm -rf "$out" && mkdir -p "$out" || exit 1
for lang in glsl hlsl msl cpp; do
  "$penumbra" poisson --count 64 --seed 7 --lang "$lang" -o "$out/disk.$lang" || { echo "poisson --lang $lang failed"; exit 1; }
done
{ echo "#version 450"; cat "$out/disk.glsl"
  echo "layout(location = 0) out vec4 colour; void main() { colour = vec4(PN_POISSON_DISK[63], 0.0, 1.0); }"; } > "$out/disk.frag"
"$validator" -S frag "$out/disk.frag" > "$out/glsl.log" 2>&1 || { cat "$out/glsl.log"; echo "the GLSL disk does not compile"; exit 1; }
{ cat "$out/disk.hlsl"
  echo "float4 main() : SV_Target { return float4(PN_POISSON_DISK[63], 0.0, 1.0); }"; } > "$out/disk_ps.hlsl"
"$validator" -D -e main -S frag -V "$out/disk_ps.hlsl" -o "$out/disk_ps.spv" > "$out/hlsl.log" 2>&1 ||
  { cat "$out/hlsl.log"; echo "the HLSL disk does not compile"; exit 1; }
{ echo "#include <cstdio>"; cat "$out/disk.cpp"
  printf '%s\n' 'int main() { for (const auto& p : PN_POISSON_DISK) std::printf("%.9g %.9g\n", p[0], p[1]); }'; } \
  > "$out/disk_main.cpp"
"$cxx" -std=c++17 -Wall -Werror -o "$out/disk_main" "$out/disk_main.cpp" || { echo "the C++ disk does not compile"; exit 1; }
"$out/disk_main" > "$out/cpp_points.txt" || exit 1
/usr/bin/python3 - "$out" <<'PY' || exit 1
import re, sys
out = sys.argv[1]
def points(text):
    body = text.split("=", 1)[1]
    return [float(v.rstrip("f")) for v in re.findall(r"(?<![A-Za-z0-9_.])-?[0-9][0-9.e+-]*f?", body)]
glsl = points(open(f"{out}/disk.glsl").read())
assert len(glsl) == 128, f"GLSL: {len(glsl)} values, expected 128"
for lang in ("hlsl", "msl", "cpp"):
    values = points(open(f"{out}/disk.{lang}").read())
    assert values == glsl, f"{lang}: its values differ from the GLSL's"
printed = [float(v) for v in open(f"{out}/cpp_points.txt").read().split()]
assert printed == glsl, "the C++ program's points differ from the GLSL's"
print("poisson --lang: 64 points, GLSL and HLSL compile, the C++ program prints them, MSL's text holds them")
PY
