#!/usr/bin/env python3
"""check_vulkan.py PENUMBRA SCRATCH GL_CHECK API

The Vulkan executor against GL 4.5, side by side (issue 27), one API a run (vulkan or hlsl: two
CTests, so that two cores share what one ran serially):
- `penumbra info --api vulkan` names a device and has the validation layer on;
- `penumbra check -v --quick` on API against GL_CHECK, every case on GL 4.5 (cli_check_all_gl,
  check_all_gl.sh): every registered check passes on both, and every case the API ran is one of
  GL's (the same name) — --quick runs every program on fewer fixtures (docs/reliability.md: the
  suite's 8 minutes);
- hlsl: every export written with an engine's register plan (PLAN: every register kind shifted,
  space 2: issue 53) and bound there, as the engine binds it;
- hlsl: an HLSL copy given with --hlsl-root is what runs: exact_pcss.glsl's export (`bundle
  --target hlsl` with the plan, the file an engine takes) passes the exports check as written and
  fails with one operator changed, with a where / expected / observed line.
Exit 77 (skipped) when there is no Vulkan device.
"""
import os
import re
import shutil
import subprocess
import sys

CASE = re.compile(r'^([a-z_]+): (pass|FAIL) (.*?): ')
ROW = re.compile(r'^([a-z_]+)\s+(\d+|-)\s+.*\s(pass|FAIL)$')
WHERE = re.compile(r'exports: FAIL .* at \([0-9]+, [0-9]+\)(\[[0-9]\])?: expected [-+0-9.einf]+, observed [-+0-9.einf]+')


# An engine's register plan (DXC's -fvk-*-shift habit): each kind its own range, in space 2.
PLAN = ('--register-shift', 't=16,s=8,u=32,b=48', '--register-space', '2')


def run(*args):
    return subprocess.run(args, capture_output=True, text=True, timeout=600)


def table(output):
    """{module: (cases, verdict)} from a check's table, {module: set of case names} from -v lines."""
    rows, cases = {}, {}
    for line in output.splitlines():
        m = ROW.match(line)
        if m:
            rows[m.group(1)] = (m.group(2), m.group(3))
        m = CASE.match(line)
        if m:
            cases.setdefault(m.group(1), set()).add(m.group(3))
    return rows, cases


def main():
    penumbra, scratch, gl_check, api = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
    if api not in ('vulkan', 'hlsl'):
        print(f'API {api!r}: expected vulkan or hlsl')
        return 2
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

    if not os.path.exists(gl_check):
        print(f'SKIPPED: no GL run of the checks ({gl_check}: cli_check_all_gl did not run or had no context)')
        return 77
    with open(gl_check) as f:
        runs = {'gl450': table(f.read())}
    r = run(penumbra, 'check', '-v', '--quick', '--api', api, *(PLAN if api == 'hlsl' else ()))
    if r.returncode != 0:
        print(r.stdout + r.stderr)
        print(f'check --api {api}: exit {r.returncode}, expected 0')
        return 1
    runs[api] = table(r.stdout)

    failures = []
    if api == 'hlsl' and 'registers t+16 s+8 u+32 b+48, space 2' not in r.stdout:
        failures.append('check --api hlsl with the plan: its header does not name the plan (t+16 s+8 u+32 b+48, space 2)')
    modules = sorted(runs['gl450'][0])
    print(f'{"module":16} {"gl450":>14} {api:>14}')
    for module in modules:
        cells = []
        for a in ('gl450', api):
            cases, verdict = runs[a][0].get(module, ('-', 'absent'))
            cells.append(f'{cases} {verdict}')
        print(f'{module:16} {cells[0]:>14} {cells[1]:>14}')
        gl_names = runs['gl450'][1].get(module, set())
        verdict = runs[api][0].get(module, ('', 'absent'))[1]
        names = runs[api][1].get(module, set())
        if verdict != 'pass' or runs['gl450'][0][module][1] != 'pass':
            failures.append(f'{module}: {api} {verdict}, gl450 {runs["gl450"][0][module][1]}: expected pass on both')
        if not names or not names <= gl_names:
            failures.append(f'{module}: {api} ran {len(names)} cases, GL {len(gl_names)}: expected some, each one '
                            f'of GL\'s (first not: {sorted(names - gl_names)[:2]})')
    if len(modules) < 23:
        failures.append(f'only {len(modules)} checks ran: {modules}')
    if api == 'vulkan':
        for f in failures:
            print('FAIL ' + f)
        return 1 if failures else 0

    # An HLSL copy is what runs: exact_pcss.glsl's export — the file an engine takes — given with
    # --hlsl-root passes the exports check as written, and fails with one operator changed.
    root = os.path.join(scratch, 'hlsl')
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    export = os.path.join(root, 'exact_pcss.hlsl')
    b = run(penumbra, 'bundle', 'exact_pcss.glsl', '--target', 'hlsl', '--shader-model', '5.1', *PLAN, '-o', export)
    if b.returncode != 0:
        print(b.stdout + b.stderr)
        return 1
    good = run(penumbra, 'check', 'exports', '--quick', '--api', 'hlsl', *PLAN, '--hlsl-root', root)
    if good.returncode != 0:
        failures.append('exports on exact_pcss.glsl\'s HLSL export: exit %d, expected 0\n%s' % (good.returncode, good.stdout))
    text = open(export).read()
    mistake = text.replace('return 1.0f - pnPcfOccludedFraction(', 'return 1.0f - 0.5f * pnPcfOccludedFraction(', 1)
    if mistake == text:
        failures.append('could not put the mistake into exact_pcss.hlsl (return 1.0f - pnPcfOccludedFraction()')
    else:
        open(export, 'w').write(mistake)
        bad = run(penumbra, 'check', 'exports', '--quick', '--api', 'hlsl', *PLAN, '--hlsl-root', root)
        print(bad.stdout, end='')
        if bad.returncode != 1 or not WHERE.search(bad.stdout):
            failures.append(f'exports on a broken HLSL copy: exit {bad.returncode}, expected 1 with a where / expected / observed line')
    shutil.rmtree(root, ignore_errors=True)

    for f in failures:
        print('FAIL ' + f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
