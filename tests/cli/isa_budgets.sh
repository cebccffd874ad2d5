#!/bin/sh
# isa_budgets.sh PENUMBRA GLSL_DIR SCRATCH
# `penumbra isa --budgets` on RDNA 2 wave64 (Mesa's RADV on its null device: no GPU): every
# technique's call as an engine compiles it within the budget its module's header writes, and no
# entry (engine calls, every pass and export) uses scratch. (The runner's technique passes, the
# same modules under the runner's defines, half this run's time, compile in cli_bench_frontier_quick
# for its estimates; `penumbra isa` shows them.) Then four copies
# of GLSL_DIR that must fail: Fast PCSS's call keeping a local array (scratch), its budget line
# lowered below what it takes (instructions, and a loop body's cycles), and a budget line that
# does not parse.
set -u
penumbra=$1 glsl=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1
out=$("$penumbra" isa --families navi21 --waves 64 --budgets --kinds engine pass --json "$scratch/isa.json" 2>&1)
status=$?
printf '%s\n' "$out" | grep "isa: \(budgets\|over budget\)"
[ "$status" -eq 0 ] || { printf '%s\n' "$out" | tail -5; echo "expected exit 0 on the library, got $status"; exit 1; }
python3 - "$scratch/isa.json" <<'PY' || exit 1
import json, sys
j = json.load(open(sys.argv[1]))
t = j["targets"][0]
assert t["family"] == "navi21" and t["wave"] == 64 and "NAVI21" in t["device"], t["device"]
kinds = {(s["name"], s["kind"], s["stage"]) for s in t["shaders"]}
for need in [("fast_pcss", "engine", "compute"), ("fast_pcss", "engine", "fragment"),
             ("poisson_pcss", "engine", "compute"), ("passes/blur.comp", "pass", "compute")]:
    assert need in kinds, need
for s in t["shaders"]:
    f = s["figures"]
    assert f["vgprs"] > 0 and f["instructions"] > 0 and f["code_bytes"] > 0, s["name"]
    assert f["scratch_bytes"] == 0, s["name"]
print("isa json: %d shaders, every one with registers, instructions and code, none with scratch" % len(t["shaders"]))
PY

copy="$scratch/glsl"
# on_copy EDIT MARK STATUS WHAT: a copy of GLSL_DIR with the perl substitution EDIT made in
# fast_pcss.glsl (whole file, /m), which must then hold MARK; `isa --budgets` on its Fast PCSS call
# must exit STATUS. Leaves the output in $out.
on_copy() {
  rm -rf "$copy" && cp -r "$glsl" "$copy" || exit 1
  perl -0pi -e "$1" "$copy/fast_pcss.glsl"
  grep -q -- "$2" "$copy/fast_pcss.glsl" || { echo "could not put $4 into the copy"; exit 1; }
  out=$("$penumbra" isa --families navi21 --waves 64 --kinds engine --only fast_pcss --budgets --glsl-root "$copy" 2>&1)
  status=$?
  printf '%s\n' "$out" | grep "isa: \(budgets\|over budget\)"
  [ "$status" -eq "$3" ] || { printf '%s\n' "$out"; echo "expected exit $3 with $4, got $status"; exit 1; }
}

# Fast PCSS's call keeps a local array indexed per pixel: scratch memory.
on_copy 's/(float pnFastPcss\(sampler2D map, sampler2D mip, sampler2D sampleTable, PnLight light, vec3 receiver, ivec2 pixel,\n\s*PnFastPcssSettings settings\) \{\n)/$1  float kept[256];\n  for (int i = 0; i < 256; ++i) kept[i] = receiver.z * float(i);\n  if (kept[(pixel.x * 7 + pixel.y) & 255] < 0.0) return 0.5;\n/' \
  'float kept\[256\]' 1 "a local array"
printf '%s\n' "$out" | grep -q "over budget: fast_pcss engine compute: [0-9]* scratch > 0 (fast_pcss.glsl:" ||
  { echo "no line naming Fast PCSS's scratch and its budget"; exit 1; }

# The budget lowered below what the call takes.
on_copy 's/^(\/\/ isa budget: vgprs \d+, instructions )\d+/${1}100/m' 'instructions 100,' 1 "the budget at 100 instructions"
printf '%s\n' "$out" | grep -q "over budget: fast_pcss engine fragment: [0-9]* instructions > 100" ||
  { echo "no line naming the instructions over budget"; exit 1; }

# The loop budget lowered below the costliest loop body's cycles (Step 3's refinement, ~340).
on_copy 's/^(\/\/ isa budget: .*?, loop )\d+/${1}100/m' 'loop 100,' 1 "the loop budget at 100 cycles"
printf '%s\n' "$out" | grep -q "over budget: fast_pcss engine compute: [0-9]* loop > 100" ||
  { echo "no line naming the loop body over budget"; exit 1; }

# A budget line that does not parse: a bad-input error naming the line.
on_copy 's/^\/\/ isa budget: vgprs \d+/\/\/ isa budget: vgprs lots/m' 'vgprs lots' 2 "an unreadable budget line"
printf '%s\n' "$out" | grep -q "fast_pcss.glsl:[0-9]*: isa budget item 'vgprs lots'" ||
  { printf '%s\n' "$out"; echo "no line naming the unreadable budget item"; exit 1; }
rm -rf "$scratch"
echo "isa budgets: the library within; a local array, a lowered budget and a bad budget line caught"
