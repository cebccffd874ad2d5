#!/usr/bin/env python3
"""The runner's floor rules, held: every #include under runner/ against the table
in docs/architecture.md ("Floors"), the one place the rules are written.

  floor_rules.py ROOT               exit 0 when every include keeps the rules, 1 (each
                                    break on a line: file:line, the include, what the
                                    folder may include) when one does not, or when a
                                    row names a folder its floor never includes; 2 when the
                                    table cannot be read or is not a floor plan
  floor_rules.py ROOT --broken-copy the same check on a copy of ROOT with one include
                                    added back up a floor: exit 0 only when the check
                                    fails on that include and on nothing else

An include resolves as the compiler's quoted form does for the runner: a path that
exists under runner/ is that folder's file; one under glsl/ or fixtures/ (the headers
GLSL and C++ share, the fixtures' data) is allowed from every floor; anything else is
a system or library header. Every header name under runner/, glsl/, fixtures/, examples/, tests/
and fuzz/ is unique too (issue 41: an include path names one file), or the check fails naming them.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
ROW = re.compile(r'^\|\s*`([a-z_]+)/`\s*\|([^|]*)\|')


def read_rules(root):
    """{folder: set of folders it may include}, from the table under '## Floors'."""
    path = os.path.join(root, 'docs', 'architecture.md')
    rules, in_section = {}, False
    with open(path, encoding='utf-8') as f:
        for line in f:
            if line.startswith('## '):
                in_section = line.strip() == '## Floors'
                continue
            m = ROW.match(line) if in_section else None
            if m:
                allowed = set(re.findall(r'`([a-z_]+)/`', m.group(2)))
                rules[m.group(1)] = allowed
    if not rules:
        raise SystemExit(f'{path}: no "## Floors" table of | `folder/` | `may/`, `include/` | rows')
    return rules


def check_plan(rules):
    """The table must name only its own folders and be a floor plan: no cycle."""
    problems = []
    for folder, allowed in rules.items():
        for other in sorted(allowed - set(rules)):
            problems.append(f'floor table: {folder}/ may include {other}/, which has no row')
        if folder in allowed:
            problems.append(f'floor table: {folder}/ lists itself')
    state = {}

    def visit(folder, chain):
        if state.get(folder) == 'done':
            return
        if state.get(folder) == 'open':
            problems.append('floor table: a cycle, ' + ' -> '.join(chain + [folder]))
            return
        state[folder] = 'open'
        for other in sorted(rules.get(folder, ())):
            visit(other, chain + [folder])
        state[folder] = 'done'

    for folder in sorted(rules):
        visit(folder, [])
    return problems


def check_includes(root, rules):
    runner = os.path.join(root, 'runner')
    breaks, files, used = [], 0, {}
    folders = sorted(d for d in os.listdir(runner) if os.path.isdir(os.path.join(runner, d)))
    for folder in folders:
        if folder not in rules:
            breaks.append(f'runner/{folder}/: a folder without a row in docs/architecture.md\'s floor table')
            continue
        for dirpath, _, names in os.walk(os.path.join(runner, folder)):
            for name in sorted(names):
                if not name.endswith(('.h', '.cpp')):
                    continue
                files += 1
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                with open(path, encoding='utf-8') as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = m.group(1)
                        head = target.split('/')[0]
                        if '/' not in target or head == folder:
                            continue
                        if not os.path.isfile(os.path.join(runner, target)):
                            continue  # glsl/, fixtures/ or a library header
                        used.setdefault(folder, set()).add(head)
                        if head not in rules[folder]:
                            may = ', '.join(f'{d}/' for d in sorted(rules[folder])) or 'nothing above it'
                            breaks.append(f'{rel}:{number}: includes {target}: {folder}/ may include only {may}')
    for folder in folders:
        for other in sorted(rules.get(folder, set()) - used.get(folder, set())):
            breaks.append(f'floor table: {folder}/ lists {other}/, but nothing in runner/{folder}/ includes it '
                          f'(a row names only what its floor needs)')
    return breaks, files


def repeated_header_names(root):
    """Header names that more than one file under the source folders has: with every name unique,
    an include path ("modules/blur_face.h", "passes/blur_bindings.h", "vsm.h") names one file."""
    seen = {}
    for top in ('runner', 'glsl', 'fixtures', 'examples', 'tests', 'fuzz'):
        for dirpath, _, names in os.walk(os.path.join(root, top)):
            for name in names:
                if name.endswith('.h'):
                    seen.setdefault(name, []).append(os.path.relpath(os.path.join(dirpath, name), root))
    return [f'{name}: {len(paths)} headers share the name ({", ".join(sorted(paths))}): rename one'
            for name, paths in sorted(seen.items()) if len(paths) > 1]


def run(root):
    try:
        rules = read_rules(root)
    except OSError as e:
        print(f'floor rules: {e}', file=sys.stderr)
        return 2
    problems = check_plan(rules)
    if problems:
        print('\n'.join(problems))
        return 2
    breaks, files = check_includes(root, rules)
    if os.path.isdir(os.path.join(root, 'glsl')):  # the broken copy holds runner/ alone
        breaks += repeated_header_names(root)
    if breaks:
        print('\n'.join(breaks))
        print(f'floor rules: {len(breaks)} include(s) break the rules in {files} files')
        return 1
    print(f'floor rules: {files} files under runner/ keep the {len(rules)} folders\' rules')
    return 0


def broken_copy(root):
    """One include back up a floor in a copy: the check must fail on it, and only on it."""
    victim, back = 'runner/pass_runners/blur_pass.h', 'frame/technique.h'
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copytree(os.path.join(root, 'runner'), os.path.join(tmp, 'runner'))
        os.makedirs(os.path.join(tmp, 'docs'))
        shutil.copy(os.path.join(root, 'docs', 'architecture.md'), os.path.join(tmp, 'docs'))
        with open(os.path.join(tmp, victim), 'a', encoding='utf-8') as f:
            f.write(f'#include "{back}"\n')
        out = subprocess.run([sys.executable, __file__, tmp], capture_output=True, text=True)
    lines = [l for l in out.stdout.splitlines() if not l.startswith('floor rules:')]
    expected = f'{victim}:'
    if out.returncode == 1 and len(lines) == 1 and lines[0].startswith(expected) and back in lines[0]:
        print(f'broken copy caught: {lines[0]}')
        return 0
    print(f'broken copy NOT caught as expected (exit {out.returncode}; want 1 and one line naming {victim}):')
    print(out.stdout + out.stderr)
    return 1


if __name__ == '__main__':
    args = sys.argv[1:]
    if not args or args[0].startswith('-'):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(broken_copy(args[0]) if args[1:] == ['--broken-copy'] else run(args[0]))
