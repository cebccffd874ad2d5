#!/bin/sh
# bench_frontier_quick.sh PENUMBRA WORKDIR
# `penumbra bench frontier --quick` (through gl_or_skip.sh: exit 77 without a
# GL context) as CI runs it: the tables with Fast PCSS's standing, a JSON with
# its 8 points (2 scenes × 2 sizes, 128² and 256², × 2 widths), each with at least one row on the
# frontier and the cost proxy beside the PCSS rows, issue 52's rows (fast against Poisson: the
# estimate's ratio and growth, recomputed here from the points; the unbounded walk's MAE and SSIM
# beside them), and the PNG plots (the frontier's; issue 52's panels alone, --goal-plot).
penumbra=$1 work=$2
here=$(dirname "$0")
rm -rf "$work" && mkdir -p "$work" || exit 1
sh "$here/gl_or_skip.sh" "$penumbra" "fast on the frontier: (yes|no)" \
  bench frontier --quick --json "$work/frontier.json" --plot "$work/frontier.png" --goal-plot "$work/goal.png"
status=$?
[ "$status" -eq 0 ] || exit "$status"
/usr/bin/python3 - "$work/frontier.json" <<'PY' || exit 1
import json, sys
doc = json.load(open(sys.argv[1]))
points = doc["results"]["points"]
assert len(points) == 8, f"expected 8 points, found {len(points)}"
for p in points:
    where = f"{p['scene']} {p['size']} x{p['width']:g}"
    assert any(r["on_frontier"] for r in p["rows"]), f"{where}: no row on the frontier"
    fast = [r for r in p["rows"] if r["technique"] == "fast"]
    assert fast and fast[0]["fetches_per_pixel"] is not None, f"{where}: fast has no fetch count"
    assert fast[0]["fetch_tile_max"] >= fast[0]["fetches_per_pixel"], f"{where}: tile max below the mean"
    # The GPU cost estimate (docs/isa.md): every row has one, and the estimate's frontier is marked.
    assert all(r["estimate_ms"] is not None and r["estimate_ms"] > 0 for r in p["rows"]), f"{where}: a row has no estimate"
    assert any(r["on_estimate_frontier"] for r in p["rows"]), f"{where}: no row on the estimate's frontier"
assert doc["results"]["estimate"] == "navi21 wave64", doc["results"]["estimate"]
# Issue 52's yardstick: a row a point, its ratios recomputed here from the points' rows.
goal = doc["results"]["fast_against_poisson"]
assert len(goal) == 8, f"expected 8 goal rows, found {len(goal)}"
def est(p, t):
    return next(r["estimate_ms"] for r in p["rows"] if r["technique"] == t)
for g, p in zip(goal, points):
    where = f"{p['scene']} {p['size']} x{p['width']:g}"
    assert (g["scene"], g["size"], g["width"]) == (p["scene"], p["size"], p["width"]), where
    assert abs(g["estimate_ratio"] - est(p, "fast") / est(p, "poisson")) <= 1e-9 * g["estimate_ratio"], where
    first = min((q for q in points if (q["scene"], q["size"]) == (p["scene"], p["size"])), key=lambda q: q["width"])
    assert abs(g["growth"] - est(p, "fast") / est(first, "fast")) <= 1e-9 * g["growth"], where
    assert g["cost_bound"] == (1.0 if p["width"] == first["width"] else 2.0), where
    assert g["closer"] == (g["fast_mae"] <= g["poisson_mae"] and g["fast_ssim"] >= g["poisson_ssim"]), where
    # The unbounded walk (fast without its work budget) ran beside them, its MAE and SSIM the row's.
    unbounded = next(r for r in p["rows"] if r["technique"] == "fast:leaf-divisor=0:leaf-mode=sampled")
    assert (g["unbounded_mae"], g["unbounded_ssim"]) == (unbounded["mae"], unbounded["ssim"]), where
    ratio = unbounded["estimate_ms"] / est(p, "poisson")
    assert abs(g["unbounded_estimate_ratio"] - ratio) <= 1e-9 * ratio, where
print("frontier.json: 8 points, a frontier in each, fast's fetch proxy, an estimate for every row, fast against Poisson at each")
PY
for png in frontier.png goal.png; do
  signature=$(head -c 8 "$work/$png" | od -An -tx1 | tr -d ' \n')
  [ "$signature" = "89504e470d0a1a0a" ] || { echo "$work/$png is not a PNG ($signature)"; exit 1; }
  echo "$png: PNG, $(wc -c < "$work/$png") bytes"
done
