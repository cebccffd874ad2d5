#!/usr/bin/env python3
"""interface_tables.py ROOT PENUMBRA [--write]

Issue 53 item 2: each pass an engine is told to build with has its resource interface on its
module's page, between `<!-- interface MODULE -->` and `<!-- /interface -->`, exactly as
`penumbra bundle MODULE --interface` reads it from the pass's SPIR-V (binding, HLSL register,
kind, format, access, whether the entry uses it, what it holds). Fails naming the page and the first
line that differs, or a required pass without a table; --write puts the tables in. Exit 0 / 1.
"""
import os
import re
import subprocess
import sys

REQUIRED = ['passes/minmax_mip_build.comp', 'passes/blur.comp', 'passes/depth_pyramid_build.comp',
            'passes/summed_area_build.comp', 'passes/vsm_moments.comp', 'passes/shadow_depth_peel.frag']
MARKER = re.compile(r'(<!-- interface (\S+) -->\n)(.*?)(<!-- /interface -->)', re.S)


def main():
    root, penumbra = sys.argv[1:3]
    write = '--write' in sys.argv[3:]
    failures, found = [], set()
    for folder, _, files in sorted(os.walk(os.path.join(root, 'docs'))):
        for name in sorted(files):
            if not name.endswith('.md'):
                continue
            path = os.path.join(folder, name)
            page = open(path, encoding='utf-8').read()
            if '<!-- interface ' not in page:
                continue
            rel = os.path.relpath(path, root)

            def table(m):
                module = m.group(2)
                found.add(module)
                r = subprocess.run([penumbra, 'bundle', module, '--interface', '--glsl-root', os.path.join(root, 'glsl')],
                                   capture_output=True, text=True, timeout=120)
                if r.returncode != 0:
                    failures.append(f'{rel}: {module}: bundle --interface failed: {r.stderr.strip()}')
                    return m.group(0)
                if m.group(3) != r.stdout:
                    have, want = m.group(3).split('\n'), r.stdout.split('\n')
                    line = next((i for i in range(max(len(have), len(want)))
                                 if i >= len(have) or i >= len(want) or have[i] != want[i]), 0)
                    if not write:
                        failures.append(f'{rel}: {module}\'s table differs from its code at table line {line + 1}: '
                                        f'page "{have[line] if line < len(have) else ""}", code '
                                        f'"{want[line] if line < len(want) else ""}"')
                return m.group(1) + r.stdout + m.group(4)

            updated = MARKER.sub(table, page)
            if write and updated != page:
                open(path, 'w', encoding='utf-8').write(updated)
    for module in REQUIRED:
        if module not in found:
            failures.append(f'{module}: no `<!-- interface {module} -->` table on any page')
    for f in failures:
        print('FAIL ' + f)
    print(f'interface tables: {len(found)} passes, {len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
