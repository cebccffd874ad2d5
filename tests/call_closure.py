#!/usr/bin/env python3
"""Each module's closure — what `#include "<module>.glsl"` pulls into an engine's shader with the
default options — stated on its page and held (issue 41 §2: a call includes only what it uses).

  call_closure.py ROOT GLSLANG            exit 0 when every docs/modules/<m>.md of a module
                                          glsl/<m>.glsl states its closure as measured now, 1 (the
                                          line it should hold) when one does not
  call_closure.py ROOT GLSLANG --write    rewrite the pages' lines to the measured closure

The closure is measured, not read: glslangValidator -E preprocesses a shader holding only the
include (so an option's #ifdef'd include counts only when the option is defined), and its #line
markers name every file it read. Lines are the files' lines as a paste copies them; "of code" leaves
out blank and comment-only lines.
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'mutation'))
import mutate  # noqa: E402  (a module is a file whose header has a use: section)

MARK = '**Closure**'


def closure(glsl, validator, module):
    """The files (relative to glsl/) that including the module reads, in include order."""
    with tempfile.TemporaryDirectory() as tmp:
        shader = os.path.join(tmp, 'closure.frag')
        with open(shader, 'w', encoding='utf-8') as f:
            f.write(f'#version 450\n#extension GL_GOOGLE_include_directive : require\n'
                    f'#include "{module}"\nvoid main() {{}}\n')
        out = subprocess.run([validator, '-E', f'-I{glsl}', shader], capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit(f'call_closure: glslangValidator -E failed on {module}:\n{out.stdout}{out.stderr}')
    files = []
    for name in re.findall(r'^#line \d+ "([^"]+)"', out.stdout, re.M):
        rel = os.path.relpath(name, glsl)
        if not rel.startswith('..') and rel not in files:
            files.append(rel)
    return files


def count_lines(path):
    with open(path, encoding='utf-8') as f:
        lines = f.read().split('\n')
    if lines and lines[-1] == '':
        lines.pop()
    code = sum(1 for l in lines if l.strip() and not l.strip().startswith('//'))
    return len(lines), code


def statement(glsl, validator, module):
    files = closure(glsl, validator, module)
    total = code = 0
    for rel in files:
        t, c = count_lines(os.path.join(glsl, rel))
        total, code = total + t, code + c
    return (f'{MARK}: `#include "{module}"` (default options) reads {len(files)} files, {total:,} lines '
            f'({code:,} of code): {", ".join(files)}.')


def main():
    args = sys.argv[1:]
    if len(args) not in (2, 3) or (len(args) == 3 and args[2] != '--write'):
        print(__doc__, file=sys.stderr)
        return 2
    root, validator, write = args[0], args[1], len(args) == 3
    glsl = os.path.join(root, 'glsl')
    failures, pages = [], 0
    for name in sorted(os.listdir(glsl)):
        if not name.endswith('.glsl'):
            continue
        with open(os.path.join(glsl, name), encoding='utf-8') as f:
            if mutate.use_names(f.read()) is None:
                continue
        page = os.path.join(root, 'docs', 'modules', name[:-len('.glsl')] + '.md')
        rel_page = os.path.relpath(page, root)
        if not os.path.isfile(page):
            failures.append(f'{rel_page}: missing (glsl/{name} is a module: its page states its closure)')
            continue
        pages += 1
        want = statement(glsl, validator, name)
        with open(page, encoding='utf-8') as f:
            lines = f.read().split('\n')
        found = [i for i, l in enumerate(lines) if l.startswith(MARK)]
        if write:
            if found:
                lines[found[0]] = want
            else:  # after the page's first code block: the call
                fences = [i for i, l in enumerate(lines) if l.startswith('```')]
                at = fences[1] + 1 if len(fences) >= 2 else len(lines)
                lines[at:at] = ['', want]
            with open(page, 'w', encoding='utf-8') as f:
                f.write('\n'.join(lines))
        elif not found:
            failures.append(f'{rel_page}: no "{MARK}: ..." line; it should read:\n  {want}')
        elif lines[found[0]] != want:
            failures.append(f'{rel_page}:{found[0] + 1}: the closure changed; expected:\n  {want}\nobserved:\n  '
                            f'{lines[found[0]]}')
    for f in failures:
        print(f'FAIL {f}')
    verb = 'written' if write else 'hold'
    print(f'call closure: {pages} module pages {verb} their closure; {len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
