#!/usr/bin/python3
"""crop_render.py RENDER_DIR SCENE X,Y,W,H OUT.png [--grey LO,HI] [--error-limit L] [TECHNIQUE...]

One region of `penumbra render`'s soft-shadow pictures side by side, enlarged
(nearest neighbour): a column per picture — the truth, then each TECHNIQUE
(default poisson fast) — read from RENDER_DIR/SCENE_<name>_shadow.png, with
a second row of each technique's signed error against the truth (blue: darker
than the truth, red: brighter, saturating at ±L; default 0.5, as render's
_error.png). --grey LO,HI stretches the soft shadows' grey scale (LO black,
HI white; default 0,1) so faint penumbrae show. At the left, the first
technique's whole soft shadow (same grey scale) with the region outlined. X, Y:
the region's top-left pixel, from the top left of the image.
Needs Debian's python3-matplotlib (Agg): run it with /usr/bin/python3.
Exit 2 with one line for bad arguments or a missing picture.
"""
import argparse
import os
import sys


def fail(message):
    print(f"crop_render.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def numbers(text, count, kind, what):
    try:
        values = [kind(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != count:
        fail(f"{what} '{text}': expected {count} comma-separated {kind.__name__}s")
    return values


class Parser(argparse.ArgumentParser):
    def error(self, message):
        fail(message)


def main(argv):
    parser = Parser(prog="crop_render.py")
    parser.add_argument("render_dir")
    parser.add_argument("scene")
    parser.add_argument("region")
    parser.add_argument("out")
    parser.add_argument("techniques", nargs="*", default=["poisson", "fast"])
    parser.add_argument("--grey", default="0,1")
    parser.add_argument("--error-limit", type=float, default=0.5)
    args = parser.parse_args(argv[1:])
    x, y, w, h = numbers(args.region, 4, int, "region")
    if w <= 0 or h <= 0 or x < 0 or y < 0:
        fail(f"region '{args.region}': expected X, Y >= 0 and W, H > 0")
    lo, hi = numbers(args.grey, 2, float, "grey")
    if not lo < hi:
        fail(f"grey '{args.grey}': expected LO < HI")
    if not args.error_limit > 0:
        fail(f"error limit {args.error_limit}: expected a number > 0")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.image as mpimg
        import matplotlib.pyplot as plt
        from matplotlib.patches import Rectangle
    except ImportError as e:
        fail(f"matplotlib is missing ({e}); Debian: apt-get install python3-matplotlib")

    def shadow(name):
        path = os.path.join(args.render_dir, f"{args.scene}_{name}_shadow.png")
        if not os.path.exists(path):
            fail(f"'{path}': no such file")
        image = mpimg.imread(path)
        if image.ndim == 3:
            image = image[..., 0]
        if y + h > image.shape[0] or x + w > image.shape[1]:
            fail(f"region '{args.region}' leaves '{path}' ({image.shape[1]}x{image.shape[0]})")
        return image

    truth = shadow("truth")
    columns = ["truth"] + args.techniques
    grey = dict(interpolation="nearest", cmap="gray", vmin=lo, vmax=hi)
    fig = plt.figure(figsize=(2.7 * (len(columns) + 2), 5.8))
    grid = fig.add_gridspec(2, len(columns) + 2)
    where = fig.add_subplot(grid[:, 0:2])
    where.imshow(shadow(args.techniques[0]), **grey)
    where.add_patch(Rectangle((x - 0.5, y - 0.5), w, h, fill=False, edgecolor="red", linewidth=1.5))
    where.set_title(f"{args.techniques[0]}, whole image: the crop in red", fontsize="medium")
    where.set_xticks([])
    where.set_yticks([])
    for c, name in enumerate(columns):
        top, bottom = fig.add_subplot(grid[0, c + 2]), fig.add_subplot(grid[1, c + 2])
        image = shadow(name)
        top.imshow(image[y:y + h, x:x + w], **grey)
        top.set_title("truth (ray traced)" if name == "truth" else name, fontsize="medium")
        if name == "truth":
            bottom.axis("off")
            bottom.text(0.5, 0.5, f"soft shadow: grey {lo:g} (black)\nto {hi:g} (white)\n\nerror vs truth:\n"
                        f"blue darker, red brighter,\nsaturating at ±{args.error_limit:g}", ha="center", va="center",
                        fontsize="small", transform=bottom.transAxes)
        else:
            bottom.imshow((image - truth)[y:y + h, x:x + w], interpolation="nearest", cmap="RdBu_r",
                          vmin=-args.error_limit, vmax=args.error_limit)
            bottom.set_title("error vs truth", fontsize="small")
        for ax in (top, bottom):
            ax.set_xticks([])
            ax.set_yticks([])
    fig.suptitle(f"{args.scene}: pixels x {x}..{x + w - 1}, y {y}..{y + h - 1} from the top left", fontsize="small")
    fig.tight_layout()
    try:
        fig.savefig(args.out, dpi=100)
    except OSError as e:
        fail(f"'{args.out}': cannot be written ({e})")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main(sys.argv)
