#!/usr/bin/env python3
"""The standing probe (issue 26): hostile inputs run against the runner, one row each.

probe.py PENUMBRA GLSL_DIR DATA_DIR WORK_DIR [ROWS]

Each row of ROWS (tests/probe/rows.txt) is one line:

    EXIT SECONDS NEEDS COMMAND [=~ REGEX]

COMMAND is a shell command with these names filled in: {penumbra} the runner, {glsl} the
library's modules, {data} tests/data, {work} a scratch directory holding the hostile inputs this
script makes first (hostile models, hostile copies of the modules, FIFOs, a read-only place),
{out} a fresh path the row may use as an output (it does not exist before the row). NEEDS is
`gl` when the row needs a GL context (skipped without one), `limit` when it needs the import
child's memory limit (skipped in a sanitizer run, $ASAN_OPTIONS set: those builds have none), `quiet`
when it needs the import child's standard error silenced (Assimp's own lines; a sanitizer build keeps
it for the sanitizer's reports: skipped there too), or `-`. REGEX, when given, must match
the command's output (Python's re.search): what the row is about, e.g. the loop a check names.

For every row the probe asserts what the reliability contract says (docs/reliability.md):
- no signal and no hang: the command ends by itself within SECONDS (else the row fails);
- its exit code is EXIT;
- exit 2 (bad input): the output is exactly one line, `penumbra: error: …`, and {out} was not
  made (nothing half-written);
- no temporary (`.pn-*.tmp`) is left anywhere under {work}.
Prints one line per row and a summary; exits 1 when a row fails, 77 when every row was skipped.
"""
import base64
import json
import os
import pathlib
import re
import shlex
import shutil
import signal
import struct
import subprocess
import sys


def make_hostile_inputs(work: pathlib.Path, glsl: pathlib.Path) -> None:
    """The inputs the rows name, made fresh under `work`."""
    if work.exists():
        subprocess.run(["chmod", "-R", "u+w", str(work)], check=False)
        shutil.rmtree(work)
    work.mkdir(parents=True)
    # A glTF whose nodes each draw the next one twice, 22 levels deep: 4 million instances of one
    # triangle when Assimp bakes the transforms (it used to take 10 GB before a late refusal).
    triangle = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3H", 0, 1, 2) + b"\0\0"
    levels = 22
    nodes = [{"children": [i + 1, i + 1]} for i in range(levels - 1)] + [{"mesh": 0}]
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(triangle),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(triangle).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    }
    (work / "shared_children.gltf").write_text(json.dumps(gltf))
    # A glTF whose buffer, and an OBJ whose material library, is a FIFO nobody writes.
    os.mkfifo(work / "fifo.bin")
    gltf_fifo = dict(gltf, nodes=[{"mesh": 0}], buffers=[{"byteLength": len(triangle), "uri": "fifo.bin"}])
    (work / "fifo_buffer.gltf").write_text(json.dumps(gltf_fifo))
    (work / "fifo_mtllib.obj").write_text("mtllib fifo.bin\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    # A cube so far from the origin that float cannot hold its size.
    corners = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    (work / "far_cube.obj").write_text(
        "".join(f"v {1e30 + x} {1e30 + y} {1e30 + z}\n" for x, y, z in corners) +
        "f 1 2 4 3\nf 5 6 8 7\nf 1 2 6 5\nf 3 4 8 7\nf 1 3 7 5\nf 2 4 8 6\n")
    (work / "a_directory.obj").mkdir()
    # A model whose name is not UTF-8 (the rows name it by a glob: m?.obj).
    (work / "triangle.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    shutil.copy(work / "triangle.obj", os.path.join(os.fsencode(work), b"m\xff.obj"))
    # Hostile copies of the modules: an endless loop spelled through a macro; one with a decoy.
    macro = work / "macro_loop"
    shutil.copytree(glsl, macro)
    blur = macro / "blur.glsl"
    text = blur.read_text()
    needle = "PnBlurWeights pn_blurWeightsStart(float sigma) {\n"
    if needle not in text:
        raise SystemExit(f"probe: cannot find {needle!r} in {blur}")
    text = text.replace(needle, needle + "#define PN_REPEAT while\n  float x = 0.0;\n  PN_REPEAT (x > -1.0) {\n"
                        "    x += 1.0;\n  }\n", 1)
    blur.write_text(text)
    # The same loop with a literal bound far past the guard's limit, its counter written in the body.
    counter = work / "counter_loop"
    shutil.copytree(glsl, counter)
    blur = counter / "blur.glsl"
    blur.write_text(blur.read_text().replace(needle, needle + "  for (int i = 0; i < 2000000000; ++i) {\n"
                                             "    sigma = sigma * 1.0000001 + 1e-30;\n  }\n", 1))
    # A FIFO named like one of render's outputs inside an --out directory.
    fifo_out = work / "fifo_out"
    fifo_out.mkdir()
    os.mkfifo(fifo_out / "boxes_sheet.png")
    # A module a bundle would be written onto.
    shutil.copytree(glsl, work / "bundle_copy")
    (work / "not_a_directory").write_text("a file\n")
    # Issue 39. Output targets: a symbolic link to itself, a dangling one, a file outside an --out.
    os.symlink("loop", work / "loop")
    os.symlink("dangling_target", work / "dangling")
    (work / "outside.png").write_text("not the figures' file\n")
    # --out directories holding, under one of the set's names, a FIFO, a directory, a link out of it.
    for name, entry in (("fifo_figures", "blur.png"), ("fifo_frames", "moving_frame_0001_map.png")):
        (work / name).mkdir()
        os.mkfifo(work / name / entry)
    for name, entry in (("dir_figures", "traversal_nodes.png"), ("dir_frames", "moving_frames.tsv")):
        (work / name / entry).mkdir(parents=True)
    (work / "link_figures").mkdir()
    os.symlink(work / "outside.png", work / "link_figures" / "blur.png")
    (work / "twin_figures").mkdir()
    os.symlink("reuse_groups.png", work / "twin_figures" / "blur.png")
    # Copies of the modules: an export entry that is a FIFO; a `#line 77 9` before a mistake; a
    # byte-order mark.
    fifo_export = work / "fifo_export"
    shutil.copytree(glsl, fifo_export)
    (fifo_export / "exports" / "pcf.comp").unlink()
    os.mkfifo(fifo_export / "exports" / "pcf.comp")
    line_copy = work / "line_copy"
    shutil.copytree(glsl, line_copy)
    region = line_copy / "region.glsl"
    region.write_text(region.read_text() + "#line 77 9\nfloat pnBroken() { return no_such_name; }\n")
    broken_pcf = work / "broken_pcf"
    shutil.copytree(glsl, broken_pcf)
    with open(broken_pcf / "pcf.glsl", "a") as pcf:
        pcf.write("float pnBroken( {\n")
    bom_copy = work / "bom_copy"
    shutil.copytree(glsl, bom_copy)
    for name in ("region.glsl", "passes/region_query.comp"):
        (bom_copy / name).write_bytes(b"\xef\xbb\xbf" + (bom_copy / name).read_bytes())
    # Issue 54 X16: isa budget lines that do not parse (a sign, a key twice, 20 digits).
    for copy, budget in (("budget_negative", "vgprs -1"), ("budget_twice", "vgprs 48, vgprs 10"),
                         ("budget_huge", "vgprs 12345678901234567890")):
        shutil.copytree(glsl, work / copy)
        fast = work / copy / "fast_pcss.glsl"
        fast.write_text(re.sub(r"^// isa budget:.*$", "// isa budget: " + budget, fast.read_text(), count=1, flags=re.M))
    (work / "nodocs").mkdir()  # X10: a root without docs/


def has_gl(penumbra: str) -> bool:
    return subprocess.run([penumbra, "info"], capture_output=True).returncode == 0


def main() -> int:
    if len(sys.argv) not in (5, 6):
        print(__doc__.splitlines()[2].strip(), file=sys.stderr)
        return 2
    penumbra, glsl, data, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3]), pathlib.Path(sys.argv[4])
    rows_file = pathlib.Path(sys.argv[5]) if len(sys.argv) == 6 else pathlib.Path(__file__).with_name("rows.txt")
    work = work.resolve()
    make_hostile_inputs(work, glsl)
    gl = has_gl(penumbra)
    failed, ran, skipped = 0, 0, 0
    for number, line in enumerate(rows_file.read_text().splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        expected, seconds, needs, command = line.split(None, 3)
        command, _, pattern = command.partition(" =~ ")
        if (needs == "gl" and not gl) or (needs in ("limit", "quiet") and "ASAN_OPTIONS" in os.environ):
            skipped += 1
            continue
        out = work / f"out-{number}"
        shell = command.format(penumbra=shlex.quote(penumbra), glsl=shlex.quote(str(glsl)),
                               data=shlex.quote(str(data)), work=shlex.quote(str(work)), out=shlex.quote(str(out)))
        ran += 1
        problems = []
        # Its own process group, so a hang is ended whole (the shell and what it started).
        process = subprocess.Popen(["sh", "-c", shell], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   start_new_session=True)
        try:
            raw, _ = process.communicate(timeout=float(seconds))
            status = process.returncode
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            raw, _ = process.communicate()
            status = None
            problems.append(f"did not end within {seconds} s (a hang)")
        output = raw.decode("utf-8", errors="replace")
        if status is not None:
            if status < 0 or status > 128:
                problems.append(f"ended by signal {-status if status < 0 else status - 128}")
            elif status != int(expected):
                problems.append(f"exit {status}, expected {expected}")
            if int(expected) == 2 and status == 2:
                lines = output.rstrip("\n").split("\n")
                if "ASAN_OPTIONS" in os.environ:  # a crash the import child contains: its sanitizer's own line
                    lines = [l for l in lines if not re.match(r"(AddressSanitizer:DEADLYSIGNAL|==\d+==)", l)] or [""]
                if len(lines) != 1 or not lines[0].startswith("penumbra: error: "):
                    problems.append(f"expected one line 'penumbra: error: ...', got {len(lines)} lines")
                if out.exists():
                    problems.append(f"left {out.name} behind")
            if pattern and not re.search(pattern, output):
                problems.append(f"output does not match /{pattern}/")
        left = [str(p.relative_to(work)) for p in work.rglob(".pn-*.tmp")]
        if left:
            problems.append("left temporaries: " + ", ".join(left))
        verdict = "FAIL" if problems else "ok"
        first = output.strip().split("\n")[-1][:160] if output.strip() else ""
        print(f"probe row {number}: {verdict}: {command}" + (f" -> {'; '.join(problems)}" if problems else "") +
              (f"\n    {first}" if first else ""))
        failed += bool(problems)
    print(f"probe: {ran} rows run, {failed} failed, {skipped} skipped (no GL context, or a sanitizer build)")
    if failed:
        return 1
    return 77 if ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
