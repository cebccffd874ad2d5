#!/bin/sh
# bundle_validator.sh PENUMBRA GLSLANG_VALIDATOR OUT_DIR DATA_DIR GLSL_DIR
# Every module and pass under GLSL_DIR bundles, for each target, into a file
# that Debian's glslangValidator compiles on its own; a failing bundle leaves no file.
set -u
penumbra=$1 validator=$2 out=$3 data=$4 glsl=$5
rm -rf "$out" && mkdir -p "$out" || exit 1
status=0
modules=$(cd "$glsl" && find . -name '*.glsl' -o -name '*.comp' -o -name '*.vert' -o -name '*.frag' | sed 's|^\./||' | sort)
[ -n "$modules" ] || { echo "no modules under $glsl"; exit 1; }
for module in $modules; do
  stage=comp
  case $module in *.vert) stage=vert ;; *.frag) stage=frag ;; esac
  for target in gl450 es310 vulkan; do
    file="$out/$(echo "$module" | tr / _).$target.$stage"
    "$penumbra" bundle "$module" --target "$target" -o "$file" || { echo "bundle $module $target failed"; status=1; continue; }
    # SPIR-V links the files of one call into one module: a Vulkan bundle is compiled alone.
    if [ "$target" = vulkan ] && ! "$validator" -V -o "$out/spv" "$file"; then
      echo "glslangValidator rejected $file"; status=1
    fi
    grep -q '^#line 1 0$' "$file" || { echo "$file has no integer #line marker"; status=1; }
  done
done
# GL and ES bundles: one call each, every file its own compilation unit (no -l: nothing is linked),
# each error under its file's name — a process a file cost most of this test's time.
for target in gl450 es310; do
  if ! "$validator" "$out"/*."$target".*; then echo "glslangValidator rejected a $target bundle (above)"; status=1; fi
done
if "$penumbra" bundle --glsl-root "$data/cycle" a.glsl -o "$out/cycle.comp" 2>/dev/null; then
  echo "a bundle with an include cycle succeeded"; status=1
fi
if [ -e "$out/cycle.comp" ] || ls -a "$out" | grep -q '^\.pn-.*\.tmp$'; then
  echo "a failed bundle left a file behind"; status=1
fi
exit $status
