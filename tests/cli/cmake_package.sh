#!/bin/sh
# cmake_package.sh SOURCE_DIR BUILD_DIR SCRATCH
# Issue 41 §3: the package engines consume. `cmake --install BUILD_DIR` into a fresh prefix holds the
# tool, the whole glsl/ tree and the package config, nothing else; the installed tool reads its own
# modules (bundle without --glsl-root); examples/ builds against it (find_package(penumbra),
# penumbra_bundle()); a project's bundles run again when a module changes; a wrong call to
# penumbra_bundle() fails the configure step, naming the argument (tests/data/cmake_package).
set -u
source=$1 build=$2 scratch=$3
prefix=$scratch/prefix
fail() { printf 'cmake_package: %s\n' "$1"; exit 1; }
# run LOG CMD...: CMD's output into LOG, shown when it fails.
run() { log=$1; shift; "$@" >"$log" 2>&1 || { cat "$log"; return 1; }; }
rm -rf "$scratch" && mkdir -p "$scratch" || fail "cannot make $scratch"

run "$scratch/install.log" cmake --install "$build" --prefix "$prefix" || fail "cmake --install failed"
extra=$(cd "$prefix" && find . ! -type d ! -path ./bin/penumbra ! -path './share/penumbra/glsl/*' ! -path './lib*/cmake/penumbra/*')
[ -z "$extra" ] || fail "installed files that are not the package's: $extra"
diff -r "$source/glsl" "$prefix/share/penumbra/glsl" || fail "the installed glsl/ is not the source's"

# The installed tool's default root is its own share/penumbra/glsl: it bundles a module only that copy has.
probe=$prefix/share/penumbra/glsl/only_installed.glsl
printf '// only in the installed copy\n' >"$probe"
cd "$scratch" && "$prefix/bin/penumbra" bundle only_installed.glsl --bare | grep -q "only in the installed copy" ||
  fail "the installed tool did not read its own share/penumbra/glsl"
rm "$probe"
"$prefix/bin/penumbra" bundle fast_pcss.glsl --bare -o installed_bundle.glsl || fail "the installed tool did not bundle fast_pcss.glsl"

# examples/ as an engine builds it; the glad loader the build tree's examples made, when there is one.
examples=$scratch/examples
if [ -f "$build/examples/fast_pcss/glad/src/gl.c" ]; then
  mkdir -p "$examples/fast_pcss" && cp -r "$build/examples/fast_pcss/glad" "$examples/fast_pcss/"
fi
run "$scratch/examples-configure.log" cmake -S "$source/examples" -B "$examples" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Debug || fail "examples/ does not configure against the installed package"
grep -qx "penumbra_DIR:PATH=$prefix/lib.*/cmake/penumbra" "$examples/CMakeCache.txt" ||
  fail "examples/ found another penumbra package: $(grep penumbra_DIR "$examples/CMakeCache.txt")"
run "$scratch/examples-build.log" cmake --build "$examples" -j2 || fail "examples/ does not build against the installed package"
[ -x "$examples/fast_pcss/fast_pcss_example" ] || fail "no fast_pcss_example"
[ -x "$examples/fast_pcss_vulkan/fast_pcss_vulkan_example" ] || fail "no fast_pcss_vulkan_example"
[ -s "$examples/fast_pcss/generated/sample_table.inc" ] || fail "no sample table"
cmp "$examples/fast_pcss/generated/fast_pcss_bundle.glsl" installed_bundle.glsl ||
  fail "the example's bundle is not the installed tool's bundle of fast_pcss.glsl"

# A project's bundles (the issue's HLSL call among them), and again after a module changed.
project=$scratch/project
run "$scratch/project-configure.log" cmake -S "$source/tests/data/cmake_package" -B "$project" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCASE=good || fail "a project calling penumbra_bundle() does not configure"
run "$scratch/project-build.log" cmake --build "$project" || fail "a project's bundles do not build"
grep -q "pnFastPcss" "$project/fast_pcss.hlsl" || fail "fast_pcss.hlsl is not Fast PCSS's HLSL export"
cmp -s "$project/glsl/fast_pcss_bundle.glsl" installed_bundle.glsl || fail "the project's bare bundle differs"
grep -q "^Texture2D<float4> pnDepthMap : register(t19, space2);" "$project/poisson_pcss_planned.hlsl" ||
  fail "poisson_pcss_planned.hlsl is not in the plan REGISTER_SHIFT t=16,u=32,b=48 REGISTER_SPACE 2"
touch "$prefix/share/penumbra/glsl/traversal.h"
run "$scratch/project-rebuild.log" cmake --build "$project" || fail "the rebuild failed"
[ "$(grep -c "penumbra bundle fast_pcss.glsl" "$scratch/project-rebuild.log")" -eq 2 ] ||
  fail "a changed module did not bundle both again: $(cat "$scratch/project-rebuild.log")"

# Wrong calls: each configure fails with its message.
for case in "missing_module:MODULE 'no_such.glsl': no such file under the glsl root $prefix/share/penumbra/glsl" \
            "unknown_target:TARGET 'glsl': expected one of gl450, vulkan, es310, hlsl, msl" \
            "no_output:no OUTPUT: expected OUTPUT <file> MODULE" \
            "space_without_model:REGISTER_SPACE 1: shader model 5.0 has no register spaces: expected SHADER_MODEL 5.1 or 6.0" \
            "output_directory:OUTPUT 'adir': $scratch/bad-output_directory/adir is a directory: expected a file" \
            "module_outside:MODULE '../outside.glsl': no such file under the glsl root" \
            "header_hlsl:MODULE 'fast_pcss.h' with TARGET hlsl: expected a module (.glsl) or a pass" \
            "no_export_hlsl:MODULE 'region.glsl' with TARGET hlsl: the module has no export entry exports/region.comp" \
            "output_list:OUTPUT 'a;b.glsl': a list"; do
  name=${case%%:*} message=${case#*:}
  if cmake -S "$source/tests/data/cmake_package" -B "$scratch/bad-$name" -DCMAKE_PREFIX_PATH="$prefix" \
       -DCASE="$name" >"$scratch/bad-$name.log" 2>&1; then
    fail "$name: the configure step succeeded"
  fi
  # CMake wraps a message's lines: compare with the spaces and line breaks taken out.
  tr -d ' \n' <"$scratch/bad-$name.log" | grep -qF "penumbra_bundle:$(printf '%s' "$message" | tr -d ' ')" ||
    { cat "$scratch/bad-$name.log"; fail "$name: expected 'penumbra_bundle: $message'"; }
done

cd / && rm -rf "$scratch"
echo "cmake_package: ok"
