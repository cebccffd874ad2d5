#!/usr/bin/env python3
"""bundle_cross.py PENUMBRA GLSLANG_VALIDATOR GLSL_DIR SCRATCH

`penumbra bundle --target hlsl | msl` (issue 27):
- every module with an export entry (GLSL_DIR/exports/X.comp) and every query pass, as HLSL
  shader model 5.0 and 6.0: glslangValidator's HLSL front end (-D) accepts it as a compute
  shader, and the technique's one call is there under its own name;
- the same modules as MSL (which cannot be compiled on Linux): the export is deterministic (two
  runs, the same bytes) and every resource the header lists is in the kernel's signature at the
  index the header names (SPIRV-Cross's reflection);
- a module without an export entry is refused in one line that names the entry it looked for.
"""
import glob
import os
import re
import subprocess
import sys

BINDING = re.compile(r'^//   (\w+) \(GLSL binding (\d+)\): (.*)$', re.M)


def run(*args):
    return subprocess.run(args, capture_output=True, text=True, timeout=300)


def main():
    penumbra, validator, glsl, scratch = sys.argv[1:5]
    os.makedirs(scratch, exist_ok=True)
    failures = []
    modules = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(glsl, 'exports', '*.comp')))
    passes = sorted('passes/' + os.path.basename(p) for p in glob.glob(os.path.join(glsl, 'passes', '*_query.comp')))
    if len(modules) < 8:
        failures.append(f'{len(modules)} export entries: expected one per technique (8)')
    for name in [m + '.glsl' for m in modules] + passes:
        for model in ('5.0', '6.0'):
            out = os.path.join(scratch, os.path.basename(name) + model + '.hlsl')
            b = run(penumbra, 'bundle', name, '--target', 'hlsl', '--shader-model', model, '-o', out)
            if b.returncode != 0:
                failures.append(f'bundle {name} --target hlsl --shader-model {model}: {b.stderr.strip()}')
                continue
            v = run(validator, '-D', '-V', '-S', 'comp', '-e', 'main', out, '-o', os.devnull)
            if v.returncode != 0:
                failures.append(f'{name} (HLSL {model}) refused by glslangValidator -D: {v.stdout.strip()[:300]}')
            text = open(out).read()
            if name.endswith('.glsl'):
                call = 'pn' + ''.join(w.capitalize() for w in name[:-5].split('_'))
                if name == 'vsm.glsl':
                    call = 'pnVsm'
                if not re.search(r'^float ' + call + r'\(', text, re.M):
                    failures.append(f'{name} (HLSL {model}): no function {call}(...) in the export')
        if not name.endswith('.glsl'):
            continue
        first = run(penumbra, 'bundle', name, '--target', 'msl')
        second = run(penumbra, 'bundle', name, '--target', 'msl')
        if first.returncode != 0 or first.stdout != second.stdout:
            failures.append(f'{name} (MSL): exit {first.returncode}, or two runs differ')
            continue
        bindings = BINDING.findall(first.stdout)
        kernel = re.search(r'kernel void main0\((.*?)\)\s*\{', first.stdout, re.S)
        if not bindings or not kernel:
            failures.append(f'{name} (MSL): no binding list in the header, or no kernel')
            continue
        for resource, binding, where in bindings:
            index = 'buffer' if 'buffer' in where else 'texture'
            if not re.search(r'\b' + resource + r'\w*\s*\[\[' + index + r'\(' + binding + r'\)\]\]', kernel.group(1)) and \
               not re.search(r'&\s*\w+\s*\[\[' + index + r'\(' + binding + r'\)\]\]', kernel.group(1)):
                failures.append(f'{name} (MSL): {resource} not at [[{index}({binding})]] in the kernel')
    bad = run(penumbra, 'bundle', 'region.glsl', '--target', 'hlsl')
    if bad.returncode != 2 or 'exports/region.comp' not in bad.stderr or len(bad.stderr.strip().splitlines()) != 1:
        failures.append(f'bundle region.glsl --target hlsl: exit {bad.returncode}, {bad.stderr.strip()!r}: expected '
                        'exit 2 and one line naming exports/region.comp')
    for f in failures:
        print('FAIL ' + f)
    print(f'{len(modules)} modules and {len(passes)} query passes exported as HLSL 5.0, 6.0 and MSL: '
          f'{len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
