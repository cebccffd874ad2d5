#!/usr/bin/env python3
"""check_vulkan.py PENUMBRA SCRATCH

The Vulkan executor against GL 4.5, side by side (issue 27):
- `penumbra info --api vulkan` names a device and has the validation layer on;
- `penumbra check -v` on gl450, vulkan and hlsl: every check that runs off GL passes on all three,
  with the same cases (the same names) as on GL — all of them for the checks that run every case
  off GL, a non-empty part of them for the checks whose other cases are GL passes — and every
  other check is reported "not run (GL passes)", never as passing;
- an HLSL copy given with --hlsl-root is what runs: exact_pcss.glsl's export (`bundle --target
  hlsl`, the file an engine takes) passes the exports check as written and fails with one operator
  changed, with a where / expected / observed line.
Exit 77 (skipped) when there is no Vulkan device.
"""
import os
import re
import shutil
import subprocess
import sys

CASE = re.compile(r'^([a-z_]+): (pass|FAIL) (.*?): ')
ROW = re.compile(r'^([a-z_]+)\s+(\d+|-)\s+.*\s(pass|FAIL|not run \(GL passes\))$')
WHERE = re.compile(r'exports: FAIL .* at \([0-9]+, [0-9]+\)(\[[0-9]\])?: expected [-+0-9.einf]+, observed [-+0-9.einf]+')


def run(*args):
    return subprocess.run(args, capture_output=True, text=True, timeout=600)


def table(output):
    """{module: (cases, verdict)} from a check's table, {module: set of case names} from -v lines,
    the modules that ran part of their cases ("MODULE: not run here: ...")."""
    rows, cases, partial = {}, {}, set()
    for line in output.splitlines():
        if ': not run here: ' in line:
            partial.add(line.split(':')[0])
        m = ROW.match(line)
        if m:
            rows[m.group(1)] = (m.group(2), m.group(3))
        m = CASE.match(line)
        if m:
            cases.setdefault(m.group(1), set()).add(m.group(3))
    return rows, cases, partial


def main():
    penumbra, scratch = sys.argv[1], sys.argv[2]
    info = run(penumbra, 'info', '--api', 'vulkan')
    if info.returncode == 3:
        print('SKIPPED: ' + info.stderr.strip())
        return 77
    if info.returncode != 0:
        print(info.stdout + info.stderr)
        return 1
    print(info.stdout, end='')
    if 'validation: on' not in info.stdout:
        print('the validation layer is not on: install vulkan-validationlayers (scripts/install-deps.sh)')
        return 1

    runs = {}
    for api in ('vulkan', 'hlsl'):
        r = run(penumbra, 'check', '-v', '--api', api)
        if r.returncode != 0:
            print(r.stdout + r.stderr)
            print(f'check --api {api}: exit {r.returncode}, expected 0')
            return 1
        runs[api] = table(r.stdout)
    off_gl = sorted(m for m, (_, verdict) in runs['vulkan'][0].items() if verdict != 'not run (GL passes)')
    gl = run(penumbra, 'check', '-v', *off_gl)
    if gl.returncode != 0:
        print(gl.stdout + gl.stderr)
        return 1
    runs['gl450'] = table(gl.stdout)

    failures = []
    print(f'{"module":16} {"gl450":>14} {"vulkan":>14} {"hlsl":>14}')
    for module in sorted(runs['vulkan'][0]):
        cells = []
        for api in ('gl450', 'vulkan', 'hlsl'):
            rows = runs[api][0]
            cases, verdict = rows.get(module, ('-', 'not run (GL passes)' if api != 'gl450' else 'absent'))
            cells.append(f'{cases} {verdict if verdict in ("pass", "FAIL") else "not run"}')
        print(f'{module:16} {cells[0]:>14} {cells[1]:>14} {cells[2]:>14}')
        if module not in off_gl:
            if runs['hlsl'][0].get(module, ('', ''))[1] != 'not run (GL passes)':
                failures.append(f'{module}: not run on vulkan, but run on hlsl')
            continue
        gl_names = runs['gl450'][1].get(module, set())
        for api in ('vulkan', 'hlsl'):
            verdict = runs[api][0][module][1]
            names = runs[api][1].get(module, set())
            if verdict != 'pass' or runs['gl450'][0][module][1] != 'pass':
                failures.append(f'{module}: {api} {verdict}, gl450 {runs["gl450"][0][module][1]}: expected pass on both')
            if not names or not names <= gl_names:
                failures.append(f'{module}: {api} ran cases GL does not have: {sorted(names - gl_names)[:3]}')
            if module not in runs[api][2] and names != gl_names:
                failures.append(f'{module}: {api} ran {len(names)} cases, GL {len(gl_names)}: expected the same')
    if len(off_gl) < 23:  # every check, three in part (docs/vulkan-hlsl.md, "What runs where")
        failures.append(f'only {len(off_gl)} checks ran on vulkan: {off_gl}')

    # An HLSL copy is what runs: exact_pcss.glsl's export — the file an engine takes — given with
    # --hlsl-root passes the exports check as written, and fails with one operator changed.
    root = os.path.join(scratch, 'hlsl')
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    export = os.path.join(root, 'exact_pcss.hlsl')
    b = run(penumbra, 'bundle', 'exact_pcss.glsl', '--target', 'hlsl', '-o', export)
    if b.returncode != 0:
        print(b.stdout + b.stderr)
        return 1
    good = run(penumbra, 'check', 'exports', '--api', 'hlsl', '--hlsl-root', root)
    if good.returncode != 0:
        failures.append('exports on exact_pcss.glsl\'s HLSL export: exit %d, expected 0\n%s' % (good.returncode, good.stdout))
    text = open(export).read()
    mistake = text.replace('return 1.0f - pnPcfOccludedFraction(', 'return 1.0f - 0.5f * pnPcfOccludedFraction(', 1)
    if mistake == text:
        failures.append('could not put the mistake into exact_pcss.hlsl (return 1.0f - pnPcfOccludedFraction()')
    else:
        open(export, 'w').write(mistake)
        bad = run(penumbra, 'check', 'exports', '--api', 'hlsl', '--hlsl-root', root)
        print(bad.stdout, end='')
        if bad.returncode != 1 or not WHERE.search(bad.stdout):
            failures.append(f'exports on a broken HLSL copy: exit {bad.returncode}, expected 1 with a where / expected / observed line')
    shutil.rmtree(root, ignore_errors=True)

    for f in failures:
        print('FAIL ' + f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
