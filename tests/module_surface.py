#!/usr/bin/env python3
"""A module's public surface, visible in its code (issue 41 §2), held over every module of a glsl root.

A module is a .glsl file whose header comment has a `// use:` section (tests/mutation/mutate.py
reads modules the same way). Its rules:
  - the functions its header comment names are its public calls, named pn<Name>; every other
    function it defines is penumbra's internal, named pn_<name>: another module of the library may
    call it, an engine's shader should not (it may change without notice). So a call site tells
    which it is, and a function defined as pnX that the header does not name is an error (name it
    in use: or rename it pn_x), as is a header naming a pn_ function;
  - one calling convention for settings (docs/integration.md, "The calls"): a public call that
    takes a Pn…Settings struct takes no `bias` beside it, and a Pn<T>Settings struct with a `bias`
    field has its public pn<T>Defaults(float bias).

  module_surface.py ROOT                exit 0 when every module keeps the rules, 1 (one line a
                                        break: file:line: what, what to do) when one does not
  module_surface.py ROOT --broken-copy  the check on two copies of ROOT, each with one break
                                        (an internal renamed public; a settings call given a bias
                                        beside its settings): exit 0 only when each is caught, alone
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'mutation'))
import mutate  # noqa: E402  (the modules' reader: header names, comments blanked, definitions)

PUBLIC = re.compile(r'^pn[A-Z]\w*$')
INTERNAL = re.compile(r'^pn_[a-z]\w*$')


def line_of(text, offset):
    return text.count('\n', 0, offset) + 1


def definitions(text, s):
    """[(name, offset of the name, its parameter declarations)] of the file's function definitions."""
    out = []
    for name, _, open_, _ in mutate.definitions(text, s):
        start = s.rfind(name, 0, open_)
        close = mutate.matching(s, start + len(name), '(', ')')
        params = [p.strip() for p in s[start + len(name) + 1:close].split(',') if p.strip()]
        out.append((name, start, params))
    return out


def check_module(rel, text, header):
    breaks = []
    s = mutate.blank(text)
    defs = definitions(text, s)
    first = {}
    for name, start, _ in defs:
        first.setdefault(name, start)
    for name, start in first.items():
        where = f'{rel}:{line_of(text, start)}'
        if INTERNAL.match(name):
            if name in header:
                breaks.append(f'{where}: the header names {name}, an internal (pn_): a public call is pn<Name>')
        elif PUBLIC.match(name):
            if name not in header:
                internal = 'pn_' + name[2].lower() + name[3:]
                breaks.append(f'{where}: {name} has a public name, but the header does not name it: '
                              f'list it in use: or rename it {internal}')
        elif name != 'main':
            breaks.append(f'{where}: {name} is neither pn<Name> (public) nor pn_<name> (internal): '
                          'a module\'s names must not collide with an engine\'s')
    # Settings: no bias beside a settings struct; a struct with a bias has its Defaults(bias).
    for name, start, params in defs:
        if name not in header:
            continue
        settings = [p for p in params if re.match(r'^(in\s+)?Pn\w*Settings\b', p)]
        biases = [p for p in params if re.match(r'^(in\s+)?float\s+bias$', p)]
        if settings and biases:
            breaks.append(f'{rel}:{line_of(text, start)}: {name} takes a bias beside its settings '
                          f'({settings[0].split()[-1]}): the bias is the settings\' field (docs/integration.md, "The calls")')
    for m in re.finditer(r'\bstruct\s+Pn(\w+)Settings\s*\{([^{}]*)\}', s):
        if not re.search(r'\bfloat\s+bias\s*;', m.group(2)):
            continue
        ctor = f'pn{m.group(1)}Defaults'
        if ctor not in header or not any(name == ctor and params == ['float bias'] for name, _, params in defs):
            breaks.append(f'{rel}:{line_of(text, m.start())}: Pn{m.group(1)}Settings has a bias field but the module '
                          f'has no public {ctor}(float bias)')
    return breaks


def run(root):
    breaks, modules = [], 0
    glsl = os.path.join(root, 'glsl')
    for path in sorted(mutate.walk(glsl, ('.glsl',))):
        rel = os.path.relpath(path, root).replace(os.sep, '/')
        with open(path, encoding='utf-8') as f:
            text = f.read()
        header = mutate.use_names(text)
        if header is not None:
            modules += 1
            breaks += check_module(rel, text, header)
    if breaks:
        print('\n'.join(breaks))
        print(f'module surface: {len(breaks)} break(s) in {modules} modules')
        return 1
    print(f'module surface: {modules} modules name their public calls pn<Name> in their headers, '
          'their internals pn_<name>, and keep one settings convention')
    return 0


def broken_copy(root):
    """Each break in its own copy of glsl/: the check must fail on it, and only on it."""
    cases = [
        ('glsl/backprojection_mask.glsl', 'pn_backprojectionBits', 'pnBackprojectionBits', 'pnBackprojectionBits has a public name'),
        ('glsl/poisson_pcss.glsl', 'PnLight light, vec3 receiver, PnPoissonPcssSettings settings,',
         'PnLight light, vec3 receiver, float bias, PnPoissonPcssSettings settings,', 'takes a bias beside its settings'),
    ]
    failures = 0
    for victim, old, new, expected in cases:
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copytree(os.path.join(root, 'glsl'), os.path.join(tmp, 'glsl'))
            path = os.path.join(tmp, victim)
            with open(path, encoding='utf-8') as f:
                text = f.read()
            if old not in text:
                print(f'broken copy: {victim} no longer holds "{old}": update the case')
                failures += 1
                continue
            with open(path, 'w', encoding='utf-8') as f:
                f.write(text.replace(old, new))
            out = subprocess.run([sys.executable, __file__, tmp], capture_output=True, text=True)
        lines = [l for l in out.stdout.splitlines() if not l.startswith('module surface:')]
        if out.returncode == 1 and lines and all(l.startswith(victim + ':') and expected in l for l in lines):
            print(f'broken copy caught: {lines[0]}')
        else:
            print(f'broken copy NOT caught as expected (exit {out.returncode}; want 1 and lines naming {victim}: '
                  f'"{expected}"):\n{out.stdout}{out.stderr}')
            failures += 1
    return 1 if failures else 0


if __name__ == '__main__':
    args = sys.argv[1:]
    if not args or args[0].startswith('-'):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(broken_copy(args[0]) if args[1:] == ['--broken-copy'] else run(args[0]))
