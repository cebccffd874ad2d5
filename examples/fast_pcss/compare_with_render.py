#!/usr/bin/env python3
"""The example_fast_pcss test: fast_pcss_example's pictures against the runner's.

Runs `penumbra render --model MODEL --techniques fast:receiver-plane=off` (the
runner's Fast PCSS: its G-buffer, then pnFastPcss in a compute pass, the call
without a receiver plane that the example makes; the runner's `fast` adds the
plane from its G-buffer's neighbours, which a forward pass would take from
derivatives instead) and `fast_pcss_example
--model MODEL` (the same module, bundled, called from a forward fragment
shader), both on a 512x512 shadow map and screen, and compares

  visibility   render's <model>_fast_receiver-plane-off_shadow.png   vs the example's <model>_fast_pcss_visibility.png
  lit image    render's <model>_fast_receiver-plane-off_lit.png      vs the example's <model>_fast_pcss_lit.png

per pixel, in 8-bit units scaled to [0, 1] (the max over R, G, B for the lit
image). Tolerance, stated once (TOLERANCE below), for each of the two, over
the whole screen:

  mean |difference|                         < 0.0005
  share of pixels with |difference| > 0.1   < 0.0002 (52 of 512 x 512)

Measured on llvmpipe (Mesa 22.3, 2 cores): both exactly 0, for both
pictures: the same shadow map, mip chain, sample table, receivers and
settings give the same numbers. The bound leaves room for a driver that
rounds a fragment shader differently from a compute shader (a receiver one
ulp off can flip a sampled leaf on a shadow edge: a few pixels), and none for
a wrong shadow or a different noise: each of these moves 280 to 5400 pixels
by more than 0.1 (README.md, "The test"): a bias of 0.5 instead of 0.02, the
visibility left out of the shading, no normal offset, a light 10 % wider,
no refinement, exact leaves instead of sampled ones, one sample set for every
pixel, another sample table, a mip chain with only level 0. (A bias of 0 or
0.05 moves only 8 and 3 pixels here: the normal offset already keeps
surfaces off their own shadow, so on this scene the bias is nearly idle.)

--expect-mismatch inverts the verdict: the broken copy (example_fast_pcss_broken_bias)
must fail the comparison. Exit 0: as expected; 1: not; 77: no GL context (skipped).
Standard library only: the PNGs are read by the small decoder below.
"""

import argparse
import os
import shutil
import struct
import subprocess
import sys
import zlib

TOLERANCE = {"mean": 0.0005, "share_over_0.1": 0.0002}
SIZE = 512  # shadow map and screen, render's defaults
TECHNIQUE = "fast:receiver-plane=off"  # the call the example makes
TECHNIQUE_FILE = TECHNIQUE.replace(":", "_").replace("=", "-")  # render's file stem for it
SKIP = 77


def read_png(path):
    """(width, height, channels, rows): 8-bit greyscale, RGB or RGBA, not interlaced; rows top first."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG file")
    pos, idat, header = 8, [], None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    width, height, depth, colour, _, _, interlace = header
    channels = {0: 1, 2: 3, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace != 0:
        raise ValueError(f"{path}: expected an 8-bit grey, RGB or RGBA PNG without interlacing")
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:  # sub
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 255
        elif kind == 2:  # up
            line = bytearray((a + b) & 255 for a, b in zip(line, previous))
        elif kind == 3:  # average
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:  # Paeth
            for i in range(stride):
                a = line[i - channels] if i >= channels else 0
                b, c = previous[i], previous[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        elif kind != 0:
            raise ValueError(f"{path}: row {y} has filter type {kind}")
        rows.append(line)
        previous = line
    return width, height, channels, rows


def pixel_values(path):
    """Per pixel the tuple of its R, G, B in [0, 1], rows top first; and (width, height)."""
    width, height, channels, rows = read_png(path)
    take = min(channels, 3)
    pixels = [[tuple(row[x * channels + c] / 255.0 for c in range(take)) for x in range(width)] for row in rows]
    return pixels, (width, height)


def compare(name, expected_path, observed_path):
    """Prints the measures and the worst pixel; returns True when within TOLERANCE."""
    expected, size_e = pixel_values(expected_path)
    observed, size_o = pixel_values(observed_path)
    if size_e != size_o:
        print(f"{name}: sizes differ: expected {size_e[0]}x{size_e[1]}, observed {size_o[0]}x{size_o[1]}")
        return False
    total, over, count = 0.0, 0, size_e[0] * size_e[1]
    worst = (-1.0, 0, 0)
    for y, (row_e, row_o) in enumerate(zip(expected, observed)):
        for x, (e, o) in enumerate(zip(row_e, row_o)):
            d = max(abs(a - b) for a, b in zip(e, o))
            total += d
            over += d > 0.1
            if d > worst[0]:
                worst = (d, x, y)
    mean, share = total / count, over / count
    ok = mean < TOLERANCE["mean"] and share < TOLERANCE["share_over_0.1"]
    d, x, y = worst
    fmt = lambda v: "(" + ", ".join(f"{c:.3f}" for c in v) + ")" if len(v) > 1 else f"{v[0]:.3f}"
    print(f"{name}: mean |difference| {mean:.5f} (bound < {TOLERANCE['mean']}), "
          f"pixels differing by > 0.1: {over} = {share:.5f} (bound < {TOLERANCE['share_over_0.1']}) -> "
          f"{'ok' if ok else 'FAILED'}")
    if d == 0:
        print("  no pixel differs")
    else:
        print(f"  worst pixel: where ({x}, {y}) from the top left, expected {fmt(expected[y][x])} (render), "
              f"observed {fmt(observed[y][x])} (example), |difference| {d:.3f}")
    return ok


def run(command):
    print("$ " + " ".join(command), flush=True)
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sys.stdout.write(result.stdout)
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--example", required=True, help="the fast_pcss_example binary")
    parser.add_argument("--penumbra", required=True, help="the penumbra binary")
    parser.add_argument("--model", required=True, help="a mesh file both draw")
    parser.add_argument("--work", required=True, help="a directory for both outputs (emptied first)")
    parser.add_argument("--example-arg", action="append", default=[], help="passed on to the example (repeatable)")
    parser.add_argument("--expect-mismatch", action="store_true", help="pass only when the comparison fails")
    args = parser.parse_args()

    shutil.rmtree(args.work, ignore_errors=True)
    example_dir, render_dir = os.path.join(args.work, "example"), os.path.join(args.work, "render")
    example = run([args.example, "--model", args.model, "--out", example_dir, "--size", str(SIZE)] + args.example_arg)
    if example.returncode == 1 and ("no OpenGL 4.5 context" in example.stdout or "no Vulkan device" in example.stdout):
        print("skipped: no OpenGL 4.5 context on this machine")
        return SKIP
    if example.returncode != 0:
        print(f"fast_pcss_example failed (exit {example.returncode})")
        return 1
    render = run([args.penumbra, "render", "--model", args.model, "--techniques", TECHNIQUE, "--map-size", str(SIZE),
                  "--screen", str(SIZE), "--truth-samples", "1", "--repeats", "1", "--out", render_dir])
    if render.returncode != 0:
        print(f"penumbra render failed (exit {render.returncode})")
        return 1

    stem = os.path.splitext(os.path.basename(args.model))[0]
    same = compare("visibility", os.path.join(render_dir, f"{stem}_{TECHNIQUE_FILE}_shadow.png"),
                   os.path.join(example_dir, f"{stem}_fast_pcss_visibility.png"))
    same = compare("lit image", os.path.join(render_dir, f"{stem}_{TECHNIQUE_FILE}_lit.png"),
                   os.path.join(example_dir, f"{stem}_fast_pcss_lit.png")) and same
    if args.expect_mismatch:
        print("the broken copy fails the comparison, as it must" if not same
              else "FAILED: the broken copy passes the comparison: the tolerance cannot tell a wrong shadow")
        return 0 if not same else 1
    print("the example matches penumbra render" if same else "FAILED: the example differs from penumbra render")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
