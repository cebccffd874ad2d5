#!/usr/bin/env python3
"""doc_snippets.py ROOT GLSLANG_VALIDATOR SCRATCH

Every ```glsl block in ROOT/docs (issue 41: the guide compiles as written) is compiled or checked
as the HTML comment on the line before its fence says:

  <!-- glsl: call M1 M2 ... -->     statements: the body of a fragment shader's main(), after the
                                    modules M1 M2 ... (names under glsl/) and tests/docs/prelude_*.glsl
                                    (the names the snippets use: samplers, a light, a receiver ...;
                                    a snippet's own declarations shadow them); its leading #define and
                                    #include lines go to file scope first
  <!-- glsl: file M1 M2 ... -->     declarations at file scope after those modules, before a main()
  <!-- glsl: restates M -->         a module's declarations restated (its `use:` list): every
                                    prototype and struct in the block, comments and spacing aside,
                                    is in M or the files it includes
  <!-- glsl: skip REASON -->        not GLSL as written (a placeholder), with the reason

Every technique's settings struct (`struct Pn…Settings` in glsl/M.glsl) is restated on
docs/modules/M.md a field a line, each line's comment giving its default (`default …`, or `the
caller's` where there is none) — issue 53: the fields come from the code, their meaning from the page.

compiled for gl450, vulkan and es310 with glslangValidator (the test expands the includes itself).
A block without such a comment fails, and so does a ROOT without one block (issue 54 X10: a
ROOT without docs/ read as "0 failures"). Exit 0 when every block holds, 1 otherwise; 2 with a
usage line when the arguments are wrong (missing, a validator that is not an executable file, a
SCRATCH that is not a directory or cannot be one: issue 54 X11).
"""
import os
import re
import subprocess
import sys

FENCE = re.compile(r'^(\s*)```glsl\s*$')
CLOSE = re.compile(r'^\s*```\s*$')
NOTE = re.compile(r'^\s*<!-- glsl: (call|file|restates|skip)\b(.*?)-->\s*$')
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')

HEADERS = {
    'gl450': '#version 450 core\n#define S(b) layout(binding = b)\n',
    'vulkan': '#version 450\n#define S(b) layout(set = 0, binding = b)\n',
    'es310': '#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n'
             'precision highp usampler2D;\nprecision highp sampler2DArray;\n#define S(b) layout(binding = b)\n',
}


def blocks(root):
    """(page, line of the fence, note or None, text) for every glsl block under root/docs."""
    for folder, _, files in sorted(os.walk(os.path.join(root, 'docs'))):
        for name in sorted(files):
            if not name.endswith('.md'):
                continue
            path = os.path.join(folder, name)
            lines = open(path, encoding='utf-8').read().split('\n')
            i = 0
            while i < len(lines):
                m = FENCE.match(lines[i])
                if not m:
                    i += 1
                    continue
                indent, start = len(m.group(1)), i
                body = []
                i += 1
                while i < len(lines) and not CLOSE.match(lines[i]):
                    body.append(lines[i][indent:] if lines[i][:indent].strip() == '' else lines[i])
                    i += 1
                k = start - 1
                while k >= 0 and lines[k].strip() == '':
                    k -= 1
                note = NOTE.match(lines[k]) if k >= 0 else None
                yield os.path.relpath(path, root), start + 1, note, '\n'.join(body) + '\n'
                i += 1


def expand(text, glsl, seen, here=None):
    """`text` with every #include of a file under glsl/ replaced by that file, expanded (once)."""
    out = []
    for line in text.split('\n'):
        m = INCLUDE.match(line)
        if not m:
            out.append(line)
            continue
        candidates = [os.path.join(here, m.group(1))] if here else []
        candidates += [os.path.join(glsl, m.group(1)), os.path.join(glsl, 'passes', m.group(1))]
        found = next((c for c in candidates if os.path.isfile(c)), None)
        if found is None:
            raise ValueError(f'#include "{m.group(1)}": no such file under glsl/')
        found = os.path.realpath(found)
        if found not in seen:
            seen.add(found)
            out.append(expand(open(found, encoding='utf-8').read(), glsl, seen, os.path.dirname(found)))
    return '\n'.join(out)


def normalised(text):
    text = re.sub(r'//[^\n]*', ' ', text)
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    return re.sub(r'\s+', ' ', text).strip()


def compact(text):
    return re.sub(r'\s*([(),;{}])\s*', r'\1', text)


def restated(block, module_text):
    """The block's prototypes and structs that the module's text does not have (a struct whole:
    its fields, in order)."""
    have_compact = compact(normalised(module_text))
    missing = []
    body = normalised(re.sub(r'^\s*#.*$', '', block, flags=re.M))
    for struct in re.findall(r'struct\s+\w+\s*\{[^}]*\}', body):
        if compact(struct) not in have_compact:
            missing.append(struct)
    body = re.sub(r'struct\s+\w+\s*\{[^}]*\}\s*;?', ' ', body)
    for statement in re.split(r'(?<=;)\s', body):
        s = statement.strip().rstrip(';').strip()
        if not s or '...' in s or '…' in s:  # a placeholder: `(..., int iterations)` names the rest
            continue
        if compact(s) not in have_compact:
            missing.append(s)
    return missing


def settings_documented(root, blocks_found):
    """Failures: a module's settings struct not restated on its page a field a line, each with a
    comment naming its default (or `the caller's`)."""
    failures = []
    glsl = os.path.join(root, 'glsl')
    for name in sorted(os.listdir(glsl)):
        if not name.endswith('.glsl'):
            continue
        text = open(os.path.join(glsl, name), encoding='utf-8').read()
        for struct, body in re.findall(r'^struct\s+(Pn\w*Settings)\s*\{([^}]*)\}', text, flags=re.M):
            fields = re.findall(r'^\s*\w+\s+(\w+)\s*;', body, flags=re.M)
            page = f'docs/modules/{name[:-5]}.md'
            restated = [t for (p, _, note, t) in blocks_found
                        if p == page and note is not None and note.group(1) == 'restates' and f'struct {struct}' in t]
            if not restated:
                failures.append(f'{page}: {struct} ({name}) is not restated in a `restates {name}` block')
                continue
            block = restated[0]
            for field in fields:
                line = next((l for l in block.split('\n') if re.match(rf'^\s*\w+\s+{field}\s*;', l)), None)
                if line is None:
                    failures.append(f'{page}: {struct}.{field} not on a line of its own')
                elif not re.search(r"//.*(default|the caller's)", line):
                    failures.append(f"{page}: {struct}.{field}: its comment names no default (`default …` or `the caller's`)")
    return failures


def compile_all(source, stage, validator, scratch, tag):
    failures = []
    for target, header in HEADERS.items():
        path = os.path.join(scratch, f'{tag}.{target}.{stage}')
        with open(path, 'w') as f:
            f.write(header + source)
        args = [validator, '-S', stage] + (['-V', '-o', os.devnull] if target == 'vulkan' else []) + [path]
        r = subprocess.run(args, capture_output=True, text=True, timeout=120)
        if r.returncode != 0:
            errors = [l for l in r.stdout.split('\n') if 'ERROR' in l][:3]
            failures.append(f'{target}: ' + ' | '.join(errors))
    return failures


def main():
    if sys.argv[1:2] == ['--settings-only']:  # the settings check alone (its broken-copy test)
        failures = settings_documented(sys.argv[2], list(blocks(sys.argv[2])))
        for f in failures:
            print('FAIL ' + f)
        print(f'settings structs: {len(failures)} failures')
        return 1 if failures else 0
    usage = 'usage: doc_snippets.py ROOT GLSLANG_VALIDATOR SCRATCH  (or --settings-only ROOT)'
    if len(sys.argv) != 4:
        print(f'{usage}: expected 3 arguments, got {len(sys.argv) - 1}', file=sys.stderr)
        return 2
    root, validator, scratch = sys.argv[1:4]
    problem = (f'ROOT {root!r} is not a directory' if not os.path.isdir(root) else
               f'GLSLANG_VALIDATOR {validator!r} is not an executable file'
               if not (os.path.isfile(validator) and os.access(validator, os.X_OK)) else
               f'SCRATCH {scratch!r} is not a directory' if os.path.exists(scratch) and not os.path.isdir(scratch)
               else None)
    if problem:
        print(f'{usage}: {problem}', file=sys.stderr)
        return 2
    if not os.path.isdir(os.path.join(root, 'docs')):
        print(f'FAIL {os.path.join(root, "docs")}: no such directory: expected the guide and the module pages')
        print('0 glsl blocks in docs/; 1 failures')
        return 1
    glsl = os.path.join(root, 'glsl')
    here = os.path.join(root, 'tests', 'docs')
    before = open(os.path.join(here, 'prelude_before.glsl'), encoding='utf-8').read()
    after = open(os.path.join(here, 'prelude_after.glsl'), encoding='utf-8').read()
    os.makedirs(scratch, exist_ok=True)
    failures, counts = [], {}
    for n, (page, line, note, text) in enumerate(blocks(root)):
        where = f'{page}:{line}'
        if note is None:
            failures.append(f'{where}: a glsl block without `<!-- glsl: call|file|restates|skip … -->` before it')
            continue
        kind, args = note.group(1), note.group(2).split()
        counts[kind] = counts.get(kind, 0) + 1
        try:
            if kind == 'skip':
                if not args:
                    failures.append(f'{where}: skip without a reason')
                continue
            modules = ''.join(f'#include "{m}"\n' for m in args)
            if kind == 'restates':
                missing = restated(text, expand(modules, glsl, set()))
                failures += [f'{where}: not in {" ".join(args)}: {m}' for m in missing]
                continue
            # Its leading directives (#define, #include) go to file scope, before the modules.
            lines = text.split('\n')
            lead = 0
            while lead < len(lines) and (lines[lead].lstrip().startswith('#') or lines[lead].strip() == ''
                                         or lines[lead].lstrip().startswith('//')):
                lead += 1
            directives, rest = '\n'.join(lines[:lead]), '\n'.join(lines[lead:])
            seen = set()
            source = before + '\n' + \
                expand(directives, glsl, seen) + '\n' + expand(modules, glsl, seen) + '\n' + after + '\n'
            if kind == 'call':
                source += 'layout(location = 0) out vec4 pnOut;\nvoid main() {\n' + rest + \
                          '\n  pnOut = vec4(color, 0.0);\n}\n'
            else:
                source += expand(rest, glsl, seen) + '\nlayout(location = 0) out vec4 pnOut;\n' \
                          'void main() { pnOut = vec4(color, 0.0); }\n'
            failures += [f'{where}: {f}' for f in compile_all(source, 'frag', validator, scratch, f'block{n}')]
        except ValueError as e:
            failures.append(f'{where}: {e}')
    settings = settings_documented(root, list(blocks(root)))
    failures += settings
    if not counts:
        failures.append(f'{os.path.join(root, "docs")}: no ```glsl block found: expected the guide and the module pages')
    for f in failures:
        print('FAIL ' + f)
    total = sum(counts.values())
    print(f'{total} glsl blocks in docs/: ' + ', '.join(f'{v} {k}' for k, v in sorted(counts.items())) +
          f'; the settings structs restated a field a line with their defaults; {len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
