#!/usr/bin/env python3
"""bundle_cross.py PENUMBRA GLSLANG_VALIDATOR GLSL_DIR SCRATCH

`penumbra bundle --target hlsl | msl` (issue 27):
- every module with an export entry (GLSL_DIR/exports/X.comp) and every query pass, as HLSL
  shader model 5.0 and 6.0: glslangValidator's HLSL front end (-D) accepts the 5.0 export as a
  compute shader, the 6.0 export is the same text but for its registers' `, space0` (so what
  compiles in one compiles in the other: a front end's run a file was a third of this test's
  time), and the technique's one call is there under its own name;
- the same modules as MSL (which cannot be compiled on Linux): the export is deterministic (two
  runs, the same bytes) and every resource the header lists is in the kernel's signature at the
  index the header names (SPIRV-Cross's reflection);
- every export and every pass (passes/*.comp), as HLSL 5.0, 6.0 and MSL: the header's binding
  lines are the code's own declarations (issue 41: a read-only storage buffer is a
  `ByteAddressBuffer … : register(tN)`, an image written only `access::write`), and every
  resource the code declares is in the header;
- every module's export in an engine's register plan (--shader-model 5.1, PLAN: issue 53): the
  header's registers are the plan's (GLSL binding + the kind's shift, space 2) and glslangValidator
  compiles the export to exactly those descriptor sets and bindings (register tN / sN / uN / bN
  in spaceM at binding N of set M);
- a module without an export entry is refused in one line that names the entry it looked for.
"""
import glob
import os
import re
import subprocess
import sys

BINDING = re.compile(r'^//   (\w+) \(GLSL binding (\d+)\): (.*)$', re.M)


PLAN = ('--register-shift', 't=16,s=8,u=32,b=48', '--register-space', '2')
SHIFT = {'t': 16, 's': 8, 'u': 32, 'b': 48}
DECORATION = re.compile(r'Decorate (\d+)(?:\(\w*\))? (DescriptorSet|Binding) (\d+)')


def planned_export(penumbra, validator, name, out):
    """The failures of one module's export in PLAN: its header's registers against the plan, and
    the SPIR-V glslang makes of it against the header."""
    b = run(penumbra, 'bundle', name, '--target', 'hlsl', '--shader-model', '5.1', *PLAN, '-o', out)
    if b.returncode != 0:
        return [f'bundle {name} in the plan: {b.stderr.strip()}']
    text = open(out).read()
    failures = header_matches_code(name, 'HLSL 5.1 in the plan', text)
    expected = set()
    for resource, binding, where in BINDING.findall(text):
        for register in re.findall(r'register\(([tsub])(\d+), space(\d+)\)', where):
            kind, number, space = register[0], int(register[1]), int(register[2])
            if number != int(binding) + SHIFT[kind] or space != 2:
                failures.append(f'{name}: {resource} at {kind}{number}, space{space}: expected '
                                f'{kind}{int(binding) + SHIFT[kind]}, space2 (GLSL binding {binding}, the plan)')
            expected.add((space, number, kind))
    v = run(validator, '-D', '-H', '-S', 'comp', '-e', 'main', out, '-o', os.devnull)
    if v.returncode != 0:
        return failures + [f'{name} (HLSL 5.1 in the plan) refused by glslangValidator -D: {v.stdout.strip()[:300]}']
    sets, bindings = {}, {}
    for variable, what, value in DECORATION.findall(v.stdout):
        (sets if what == 'DescriptorSet' else bindings)[variable] = int(value)
    compiled = {(sets.get(v, 0), b) for v, b in bindings.items()}
    # What the code declares but never reads (a sampler beside Load, a texture of an overload the
    # entry does not take) glslang may drop: every image and constant buffer stays.
    needed = {(space, number) for space, number, kind in expected if kind in 'ub'}
    if not needed <= compiled or not compiled <= {(space, number) for space, number, _ in expected}:
        failures.append(f'{name}: glslang put the export in the plan at (set, binding) {sorted(compiled)}, '
                        f'its header says {sorted(expected)}')
    return failures


def run(*args):
    return subprocess.run(args, capture_output=True, text=True, timeout=300)


def as_shader_model_6(text):
    """An HLSL 5.0 export as 6.0 writes it: its registers in space 0, its header naming 6.0."""
    text = re.sub(r'register\(([tsub]\d+)\)', r'register(\1, space0)', text)
    return text.replace('HLSL shader model 5.0', 'HLSL shader model 6.0')


def header_matches_code(name, language, text):
    """The failures of one export's header against its code (an empty list when they agree)."""
    head_end = 0
    for m in BINDING.finditer(text):
        head_end = max(head_end, m.end())
    code = text[head_end:]
    listed = []
    failures = []
    for resource, binding, where in BINDING.findall(text[:head_end]):
        if where == 'unused: not in the code':  # declared in GLSL, dropped by SPIRV-Cross: nothing to bind
            continue
        for declaration in where.split('; '):
            listed.append(declaration)
            if declaration not in code:
                failures.append(f'{name} ({language}): the header says {declaration!r} for {resource}, '
                                'which the code does not declare')
    if language == 'MSL':
        kernel = re.search(r'kernel void main0\((.*?)\)\s*\{', code, re.S)
        declared = re.findall(r'\[\[(?:texture|sampler|buffer)\(\d+\)\]\]', kernel.group(1)) if kernel else []
        named = [re.search(r'\[\[\w+\(\d+\)\]\]', d).group(0) for d in listed if '[[' in d]
    else:
        declared = re.findall(r'register\([tsub]\d+(?:, space\d+)?\)', code)
        named = [re.search(r'register\([^)]*\)', d).group(0) for d in listed if 'register(' in d]
    for d in declared:
        if d not in named:
            failures.append(f'{name} ({language}): the code declares {d}, which the header does not list')
    return failures


def main():
    penumbra, validator, glsl, scratch = sys.argv[1:5]
    os.makedirs(scratch, exist_ok=True)
    failures = []
    modules = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(glsl, 'exports', '*.comp')))
    passes = sorted('passes/' + os.path.basename(p) for p in glob.glob(os.path.join(glsl, 'passes', '*_query.comp')))
    if len(modules) < 8:
        failures.append(f'{len(modules)} export entries: expected one per technique (8)')
    checked = set()  # (entry, language) whose header was read against its code
    for name in [m + '.glsl' for m in modules] + passes:
        texts = {}
        for model in ('5.0', '6.0'):
            out = os.path.join(scratch, os.path.basename(name) + model + '.hlsl')
            b = run(penumbra, 'bundle', name, '--target', 'hlsl', '--shader-model', model, '-o', out)
            if b.returncode != 0:
                failures.append(f'bundle {name} --target hlsl --shader-model {model}: {b.stderr.strip()}')
                continue
            text = texts[model] = open(out).read()
            if model == '5.0':
                v = run(validator, '-D', '-V', '-S', 'comp', '-e', 'main', out, '-o', os.devnull)
                if v.returncode != 0:
                    failures.append(f'{name} (HLSL {model}) refused by glslangValidator -D: {v.stdout.strip()[:300]}')
            elif '5.0' in texts and text != as_shader_model_6(texts['5.0']):
                failures.append(f'{name}: the HLSL 6.0 export is not the 5.0 export with its registers in space0')
            failures.extend(header_matches_code(name, 'HLSL ' + model, text))
            checked.add((name, 'HLSL ' + model))
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
        failures.extend(header_matches_code(name, 'MSL', first.stdout))
        checked.add((name, 'MSL'))
    # The header against the code: every export and every pass, each language (shader model 6.0's
    # registers differ from 5.0's by `, space0` only: the other passes are read in 5.0 and MSL).
    every_pass = sorted('passes/' + os.path.basename(p) for p in glob.glob(os.path.join(glsl, 'passes', '*.comp')))
    for name in [m + '.glsl' for m in modules] + every_pass:
        for target, language in (('--shader-model=5.0', 'HLSL 5.0'), ('--shader-model=6.0', 'HLSL 6.0'), (None, 'MSL')):
            if (name, language) in checked or language == 'HLSL 6.0':
                continue
            args = [penumbra, 'bundle', name, '--target', 'msl' if language == 'MSL' else 'hlsl'] + ([target] if target else [])
            b = run(*args)
            if b.returncode != 0:
                failures.append(f'bundle {name} as {language}: {b.stderr.strip()}')
                continue
            failures.extend(header_matches_code(name, language, b.stdout))
            checked.add((name, language))
            # The pass's own header comment travels with it (issue 53): its first line, in the header.
            first = open(os.path.join(glsl, name)).readline().rstrip('\n')
            if name.startswith('passes/') and (f"{name}'s own comment" not in b.stdout or first not in b.stdout):
                failures.append(f'bundle {name} as {language}: the pass\'s own comment ({first!r}) is not in the header')
    print(f'{len(checked)} exports: the header read against the code')
    for m in modules:
        failures.extend(planned_export(penumbra, validator, m + '.glsl', os.path.join(scratch, m + '.planned.hlsl')))
    print(f'{len(modules)} module exports in the plan {" ".join(PLAN)}: the registers and glslang\'s bindings read')
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
