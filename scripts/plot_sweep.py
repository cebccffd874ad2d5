#!/usr/bin/python3
"""plot_sweep.py JSON PNG — the plot of `penumbra bench sweep --json JSON`.

Two panels per scene (and size): each technique's total GPU time in ms (log
scale) and its SSIM against the ray-traced truth on light-facing pixels,
against the light width factor, one line per technique. Techniques that did
not run at a factor (exact PCSS above --exact-up-to) have no point there.
Needs Debian's python3 and python3-matplotlib (Agg backend): run it with
/usr/bin/python3 (another python3 on PATH may lack matplotlib).
Exit 2 with one line for a missing or malformed JSON.
"""
import json
import sys


def fail(message):
    print(f"plot_sweep.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except FileNotFoundError:
        fail(f"'{path}': no such file")
    except (OSError, UnicodeDecodeError) as e:
        fail(f"'{path}': cannot be read ({e})")
    except json.JSONDecodeError as e:
        fail(f"'{path}': not JSON (line {e.lineno}: {e.msg})")
    if not isinstance(doc, dict) or doc.get("bench") != "sweep":
        fail(f"'{path}': not the JSON of `penumbra bench sweep` (no \"bench\": \"sweep\")")
    results = doc.get("results")
    if not isinstance(results, dict) or not isinstance(results.get("rows"), list):
        fail(f"'{path}': no results.rows")
    rows = []
    for i, row in enumerate(results["rows"]):
        try:
            if not row["ran"]:
                continue
            rows.append((str(row["scene"]), int(row["size"]), float(row["factor"]), str(row["technique"]),
                         float(row["total_ms"]), float(row["vs_truth"]["light_facing"]["ssim"])))
        except (KeyError, TypeError, ValueError) as e:
            fail(f"'{path}': results.rows[{i}]: malformed ({type(e).__name__}: {e})")
    if not rows:
        fail(f"'{path}': no technique ran")
    listed = results.get("techniques", [])
    if not isinstance(listed, list) or not all(isinstance(m, str) for m in listed):
        fail(f"'{path}': results.techniques: expected a list of technique names, found {json.dumps(listed)[:40]}")
    techniques = listed or sorted({r[3] for r in rows})
    return doc, rows, techniques


def main(argv):
    if len(argv) != 3:
        fail("usage: plot_sweep.py JSON PNG")
    doc, rows, techniques = load(argv[1])
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import FuncFormatter, NullFormatter
    except ImportError as e:
        fail(f"matplotlib is missing ({e}); Debian: apt-get install python3-matplotlib")

    groups = []
    for scene, size, *_ in rows:
        if (scene, size) not in groups:
            groups.append((scene, size))
    fig, axes = plt.subplots(len(groups), 2, figsize=(10, 3.6 * len(groups)), squeeze=False)
    markers = "osD^vP*X"
    for g, (scene, size) in enumerate(groups):
        time_ax, ssim_ax = axes[g]
        factors = sorted({r[2] for r in rows if r[0] == scene and r[1] == size})
        for m, technique in enumerate(techniques):
            points = sorted((r[2], r[4], r[5]) for r in rows if r[:2] == (scene, size) and r[3] == technique)
            if not points:
                continue
            x = [p[0] for p in points]
            style = dict(marker=markers[m % len(markers)], label=technique)
            time_ax.plot(x, [p[1] for p in points], **style)
            ssim_ax.plot(x, [p[2] for p in points], **style)
        for ax in (time_ax, ssim_ax):
            ax.set_xscale("log", base=2)
            ax.set_xticks(factors)
            ax.set_xticklabels([f"×{f:g}" for f in factors])
            ax.set_xlabel("light width factor")
            ax.grid(True, which="both", alpha=0.3)
        time_ax.set_yscale("log")
        time_ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        time_ax.yaxis.set_minor_formatter(NullFormatter())
        time_ax.set_ylabel("total GPU time (ms, median)")
        time_ax.set_title(f"{scene}, {size}²: time", fontsize="medium")
        ssim_ax.set_ylabel("SSIM vs truth (light-facing)")
        ssim_ax.set_title(f"{scene}, {size}²: SSIM against the truth", fontsize="medium")
        ssim_ax.legend(fontsize="small")
    renderer = doc.get("renderer", "")
    fig.suptitle(f"penumbra bench sweep — {renderer} — {doc.get('date', '')}", fontsize="small")
    fig.tight_layout()
    try:
        fig.savefig(argv[2], dpi=100)
    except OSError as e:
        fail(f"'{argv[2]}': cannot be written ({e})")
    print(f"wrote {argv[2]}")


if __name__ == "__main__":
    main(sys.argv)
