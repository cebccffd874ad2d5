#!/usr/bin/env python3
"""mutate.py PENUMBRA [options]: mutation coverage of the modules' public calls (issue 39).

A module is a .glsl file under the glsl root whose header comment (the comment lines before its
first line of code) has a `// use:` section; its public calls are the pn* names that header
names and the module defines (the use: section's, and a call named before it, as pcf.glsl's
"The call": struct lines and other modules' names are no sites). Every definition of such a name
— every overload, in #if branches too — is a mutation site, so a function added to a header is
covered without a change here. For each site this makes a copy of the whole glsl root with ONE
mutant of that definition, runs the `penumbra check`s that cover the module on the copy, and
requires the mutant to FAIL (exit 1). Kinds (a definition gets each kind that applies to it):

  ret0   `return <the return type's zero>;` as the body's first statement (`return;` for void;
         a struct: its constructor of zeros, nested; a type without a zero is skipped, noted)
  ret1   `return 1.0;` (float) / `return true;` (bool) as the first statement
  cmp    the body's first comparison negated: < and >=, <= and >, == and != swapped
         (comments, preprocessor lines, << and >> skipped)
  const  the body's first float literal x -> 1.5 x (0 -> 0.5), or without one its first
         integer literal + 1
  The mistakes people make when they edit a shader (issue 54), each the body's first site:
  swap   `.xy` <-> `.yx`; without one, the operands of a non-commutative `a - b` or `a / b`
         (names or members, not calls) exchanged
  bound  a `for` loop's bound halved: `i < E` -> `i < (E) / 2` (`<` or `<=`)
  bound1 the same bound minus one: `i < (E) - 1`
  minmax `min(` <-> `max(`; without one, `floor(` <-> `ceil(`
  offset the integer texel coordinate of a `texelFetch` + 1: `texelFetch(s, p, l)` -> `texelFetch(s, (p) + 1, l)`
  drop   a term of a sum removed: `a + b` -> `a` (b a name, a member, a number or a call)

Edits stay on their line (the return goes after the body's `{`), so diagnostics keep their lines.
A mutant's id is MODULE:FUNCTION:OVERLOAD:KIND (OVERLOAD: the definition's index among the
module's definitions of FUNCTION, in file order, from 0); the list is deterministic (--list).

Which checks cover a module is traced, not listed: the runner appends every file it reads to
$PENUMBRA_SOURCE_LOG, so each registered check (the list `penumbra check` prints for an unknown
name) is run once on the unmutated root and covers every module it read (cached under --work,
keyed by the root's content, the binary and the API). A mutant runs its module's covering checks,
the module's own check (named as the module, or its family's: OWN_CHECK) first, then the fastest first, and stops at the
first that fails. A module no check reads fails the run ("no check covers"). --checks own skips
the trace: the module's own check, and `exports` where the module has an export entry
(glsl/exports/<module>.comp); the CTest subset runs so.

Results: killed (a check failed), timeout (no verdict within --timeout: killed, counted apart),
survived (every covering check passed, and read the mutated file), unread (they passed without
reading it), stillborn (the mutant does not compile: a fault of this tool, not in the score),
equivalent (a survivor listed with its reason in tests/mutation/equivalent.txt), error (exit 2/3,
a signal). Exit 0 when every mutant is killed or listed as equivalent; 1 when one survives, is
unread, stillborn or errs, or a module has no check; 2 on bad options; 77 without a context.

  --quick          the CTest subset: ret1 (else ret0) of QUICK_CALLS and QUICK_KIND_MUTANTS, --checks own,
                   each check --quick
  --modules a,b    modules (as the table names them: blur, passes/gbuffer_receiver_plane)
  --functions f,g  only these calls;  --kinds ret0,ret1,cmp,const;  --api gl450|es310|vulkan|hlsl
  --jobs N         mutants run at once (default 1);  --timeout S  seconds a check run may take
  --markdown F, --json F   the score table / every mutant's record;  --list  the mutants, no run
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

KINDS = ('ret0', 'ret1', 'cmp', 'const', 'swap', 'bound', 'bound1', 'minmax', 'offset', 'drop')

# The CTest subset (--quick): the return-constant mutants of these calls, each run on its module's
# own check (and `exports` where the module has an export entry). Chosen for checks of a few
# seconds on llvmpipe: a technique's one-call in both overloads (pnPcf: the three-argument one is
# killed by `exports` only), building blocks of each result type (float, bool, int, vec2, vec4, a
# struct), so that the subset stays within its ~60 s of the suite on two cores.
# The techniques' one calls an engine makes (issue 39's false PASSes) and a few parts of modules
# whose own checks are short.
QUICK_CALLS = ('pnPcf', 'pnPoissonPcss', 'pnVogelPcss', 'pnFastPcss', 'pnBackprojection', 'pnSavsm', 'pnVsm',
               'pnPoissonOcclusionDisk', 'pnReceiverPlaneGradient', 'pnBlur1DVec4')

# And one mutant of each of issue 54's kinds, on modules whose own checks take about a second (the
# full run of every kind on every module is docs/reliability.md's command, minutes).
QUICK_KIND_MUTANTS = ('light_model:pnLightProject:0:swap', 'blur:pnBlur1DVec4:0:bound', 'blur:pnBlur1DVec4:0:bound1',
                      'sample_table:pnSampleTexel:0:minmax', 'sample_table:pnSample:0:offset',
                      'receiver_plane:pnReceiverPlaneThreshold:0:drop')
QUICK_KINDS = ('ret0', 'ret1') + tuple(sorted({m.rsplit(':', 1)[1] for m in QUICK_KIND_MUTANTS}))

SCALARS = {'float': '0.0', 'int': '0', 'uint': '0u', 'bool': 'false', 'double': '0.0lf'}
ONES = {'float': '1.0', 'bool': 'true'}
KEYWORDS = {'return', 'else', 'case', 'in', 'out', 'inout', 'const', 'uniform', 'struct'}
QUALIFIERS = {'highp', 'mediump', 'lowp', 'precise', 'const', 'invariant'}
COMPARISON = re.compile(r'(?<![<>=!])(<=|>=|==|!=|<|>)(?![<>=])')
FLIP = {'<': '>=', '>=': '<', '<=': '>', '>': '<=', '==': '!=', '!=': '=='}
FLOAT = re.compile(r'(?<![\w.])((?:\d+\.\d*|\.\d+)(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+)(lf|LF|f|F)?(?![\w.])')
INT = re.compile(r'(?<![\w.])(0[xX][0-9a-fA-F]+|\d+)([uU]?)(?![\w.])')
SWIZZLE = re.compile(r'\.(xy|yx)\b')
OPERAND = r'[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*'
NONCOMMUTATIVE = re.compile(r'(?<![\w.)\]])(' + OPERAND + r')(\s*[-/]\s*)(' + OPERAND + r')(?![\w.(\[])')
FOR = re.compile(r'\bfor\s*\(')
MINMAX = re.compile(r'\b(min|max)(\s*\()')
FLOORCEIL = re.compile(r'\b(floor|ceil)(\s*\()')
FETCH = re.compile(r'\btexelFetch\s*\(')
PLUS = re.compile(r'(?<=[\w)\]])(\s*\+\s*)(?![+=])')
FAIL_LINE = re.compile(r'^(\S+): FAIL (.*)$', re.M)
COMPILE_ERROR = re.compile(r'\.(glsl|comp|frag|vert|h):\d+: error:|ERROR: ')


class Usage(Exception):
    pass


# ---------------------------------------------------------------- reading the modules

def blank(text):
    """The text with comments and preprocessor lines replaced by spaces (newlines kept), so that
    offsets into it are offsets into the text."""
    out = list(text)
    i, n = 0, len(text)
    while i < n:
        if text.startswith('//', i):
            while i < n and text[i] != '\n':
                out[i] = ' '
                i += 1
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            for k in range(i, j):
                if out[k] != '\n':
                    out[k] = ' '
            i = j
        else:
            i += 1
    s = ''.join(out)
    out = list(s)
    pos, continued = 0, False
    for line in s.split('\n'):
        if continued or line.lstrip().startswith('#'):
            for k in range(pos, pos + len(line)):
                out[k] = ' '
            continued = line.rstrip().endswith('\\')
        pos += len(line) + 1
    return ''.join(out)


def use_names(text):
    """The pn* names of the module's header comment (the comment lines before its first line of
    code), in order, or None for a file without a `// use:` section (not a module). The `use:`
    section lists the public calls; a module may name its one call in a section before it (pcf.glsl:
    "The call"). Only names the module defines become mutation sites."""
    header = []
    for line in text.split('\n'):
        if line.startswith('//') or not line.strip():
            header.append(line)
        else:
            break
    if not any(re.match(r'^//\s*use:', line) for line in header):
        return None
    names = []
    for name in re.findall(r'\bpn[A-Z]\w*', '\n'.join(header)):
        if name not in names:
            names.append(name)
    return names


def matching(s, i, open_ch, close_ch):
    depth = 0
    for k in range(i, len(s)):
        if s[k] == open_ch:
            depth += 1
        elif s[k] == close_ch:
            depth -= 1
            if depth == 0:
                return k
    return -1


def definitions(text, s=None):
    """[(name, return type, body open offset, body close offset)] of the file's function
    definitions at file scope, in file order."""
    s = blank(text) if s is None else s
    depth, depths = 0, []
    for ch in s:
        depths.append(depth)
        if ch == '{':
            depth += 1
        elif ch == '}':
            depth -= 1
    found = []
    for m in re.finditer(r'\b([A-Za-z_]\w*)\s*\(', s):
        if depths[m.start()] != 0:
            continue
        before = s[:m.start()].rstrip()
        t = re.search(r'([A-Za-z_]\w*)$', before)
        if not t or t.group(1) in KEYWORDS:
            continue
        close = matching(s, m.end() - 1, '(', ')')
        if close < 0:
            continue
        k = close + 1
        while k < len(s) and s[k].isspace():
            k += 1
        if k >= len(s) or s[k] != '{':
            continue  # a prototype or a call in an initializer
        end = matching(s, k, '{', '}')
        if end < 0:
            continue
        found.append((m.group(1), t.group(1), k, end))
    return found


def struct_fields(root):
    """{struct name: [field types]} of every struct under the root (.glsl and .h files)."""
    structs = {}
    for path in sorted(walk(root, ('.glsl', '.h', '.comp', '.frag'))):
        with open(path, encoding='utf-8', errors='replace') as f:
            s = blank(f.read())
        for m in re.finditer(r'\bstruct\s+(\w+)\s*\{([^{}]*)\}', s):
            fields = []
            for decl in m.group(2).split(';'):
                words = decl.split()
                words = [w for w in words if w not in QUALIFIERS]
                if not words:
                    continue
                ftype, rest = words[0], ' '.join(words[1:])
                for var in rest.split(','):
                    arr = re.search(r'\[\s*(\w*)\s*\]', var)
                    if arr:
                        fields.append((ftype, arr.group(1)))
                    elif var.strip():
                        fields.append((ftype, None))
            structs[m.group(1)] = fields
    return structs


def zero_of(type_name, structs, seen=()):
    """The type's zero as a GLSL expression, or None."""
    if type_name in SCALARS:
        return SCALARS[type_name]
    m = re.fullmatch(r'(b|i|u|d)?vec([234])', type_name)
    if m:
        inner = {None: '0.0', 'i': '0', 'u': '0u', 'b': 'false', 'd': '0.0lf'}[m.group(1)]
        return f'{type_name}({inner})'
    if re.fullmatch(r'd?mat[234](x[234])?', type_name):
        return f'{type_name}({"0.0lf" if type_name.startswith("d") else "0.0"})'
    if type_name in structs and type_name not in seen:
        parts = []
        for ftype, size in structs[type_name]:
            z = zero_of(ftype, structs, seen + (type_name,))
            if z is None:
                return None
            if size is not None:
                if not size.isdigit():
                    return None
                z = f'{ftype}[{size}]({", ".join([z] * int(size))})'
            parts.append(z)
        return f'{type_name}({", ".join(parts)})'
    return None


def walk(root, suffixes):
    for d, _, files in os.walk(root):
        for name in files:
            if name.endswith(suffixes):
                yield os.path.join(d, name)


def modules(root):
    """{module name: (file relative to the root, [public names])} of every file with a use: header."""
    found = {}
    for path in sorted(walk(root, ('.glsl',))):
        with open(path, encoding='utf-8', errors='replace') as f:
            names = use_names(f.read())
        if names is not None:
            rel = os.path.relpath(path, root).replace(os.sep, '/')
            found[rel[:-len('.glsl')]] = (rel, names)
    return found


def reachable(root):
    """{pn* name: the entry shaders (passes/, exports/ with a main) that reach it}: each entry's
    calls followed through the definitions of the files it includes (#include, transitively), by
    name. For a survivor: whether any shader the runner compiles calls the function at all."""
    texts, includes, defs = {}, {}, {}
    for path in sorted(walk(root, ('.glsl', '.comp', '.frag', '.vert', '.h'))):
        rel = os.path.relpath(path, root).replace(os.sep, '/')
        with open(path, encoding='utf-8', errors='replace') as f:
            texts[rel] = f.read()
    for rel, text in texts.items():
        found = []
        for name in re.findall(r'^\s*#\s*include\s+"([^"]+)"', text, re.M):
            for cand in (os.path.normpath(os.path.join(os.path.dirname(rel), name)), os.path.normpath(name)):
                if cand.replace(os.sep, '/') in texts:
                    found.append(cand.replace(os.sep, '/'))
                    break
        includes[rel] = found
        s = blank(text)
        for name, _, open_, close in definitions(text, s):
            defs.setdefault(rel, []).append((name, set(re.findall(r'\b(pn(?:_|[A-Z])\w*)\s*\(', s[open_:close]))))
    reached = {}
    for entry in texts:
        if not entry.startswith(('passes/', 'exports/')) or not any(n == 'main' for n, _ in defs.get(entry, [])):
            continue
        closure, todo = set(), [entry]
        while todo:
            f = todo.pop()
            if f not in closure:
                closure.add(f)
                todo.extend(includes.get(f, ()))
        calls = {}
        for f in closure:
            for name, called in defs.get(f, []):
                calls.setdefault(name, set()).update(called)
        seen, todo = set(), list(calls.get('main', ()))
        while todo:
            name = todo.pop()
            if name not in seen:
                seen.add(name)
                todo.extend(calls.get(name, ()))
        for name in seen:
            reached.setdefault(name, []).append(entry)
    return reached


def format_float(x):
    r = repr(x)
    return r if ('.' in r or 'e' in r or 'inf' in r or 'nan' in r) else r + '.0'


def mutate_constant(body):
    """(offset in body, old, new) of the body's first float literal x -> 1.5 x (0 -> 0.5), or its
    first integer literal + 1."""
    m = FLOAT.search(body)
    if m:
        x = float(m.group(1))
        new = format_float(x * 1.5 if x != 0.0 else 0.5) + (m.group(2) or '')
        return m.start(), m.group(0), new
    m = INT.search(body)
    if m:
        lit, suffix = m.group(1), m.group(2)
        new = (hex(int(lit, 16) + 1) if lit[:2] in ('0x', '0X') else str(int(lit) + 1)) + suffix
        return m.start(), m.group(0), new
    return None


def arguments(body, open_paren):
    """[(start, end)] of the arguments of the call whose `(` is at `open_paren` (top level commas)."""
    out, depth, start = [], 0, open_paren + 1
    for i in range(open_paren, len(body)):
        c = body[i]
        if c in '([{':
            depth += 1
        elif c in ')]}':
            depth -= 1
            if depth == 0:
                out.append((start, i))
                return out
        elif c == ',' and depth == 1:
            out.append((start, i))
            start = i + 1
    return []


def edit_of(kind, body):
    """(offset in body, old, new) of `kind`'s edit of the body's first site, or None (issue 54)."""
    if kind == 'swap':
        m = SWIZZLE.search(body)
        if m:
            return m.start(1), m.group(1), m.group(1)[::-1]
        m = NONCOMMUTATIVE.search(body)
        if m:
            return m.start(), m.group(0), m.group(3) + m.group(2) + m.group(1)
        return None
    if kind in ('bound', 'bound1'):
        for m in FOR.finditer(body):
            parts = arguments(body.replace(';', ','), m.end() - 1)  # the for's three clauses
            if len(parts) < 3:
                continue
            start, end = parts[1]
            cond = re.search(r'(<=?)\s*([^&|]+?)\s*$', body[start:end])
            if not cond or not cond.group(2).strip():
                continue
            bound = cond.group(2)
            new = f'({bound}) / 2' if kind == 'bound' else f'({bound}) - 1'
            return start + cond.start(2), bound, new
        return None
    if kind == 'minmax':
        m = MINMAX.search(body) or FLOORCEIL.search(body)
        if m:
            other = {'min': 'max', 'max': 'min', 'floor': 'ceil', 'ceil': 'floor'}[m.group(1)]
            return m.start(1), m.group(1), other
        return None
    if kind == 'offset':
        for m in FETCH.finditer(body):
            args = arguments(body, m.end() - 1)
            if len(args) == 3:
                start, end = args[1]
                coord = body[start:end].strip()
                at = start + body[start:end].index(coord)
                return at, coord, f'({coord}) + 1'
        return None
    if kind == 'drop':
        for m in PLUS.finditer(body):
            after = m.end()
            term = re.match(r'\d+\.?\d*(?:[eE][+-]?\d+)?[uUfF]?|' + OPERAND, body[after:])
            if not term:
                continue
            end = after + term.end()
            if end < len(body) and body[end] == '(':  # a call: its arguments too
                args = arguments(body, end)
                if not args:
                    continue
                end = args[-1][1] + 1
            if re.match(r'\s*[*/.\[]', body[end:]):  # the term goes on (a product, an index): not a term alone
                continue
            return m.start(), body[m.start():end], ''
        return None
    return None


def mutants(root, wanted_modules=None, wanted_functions=None, kinds=KINDS):
    """(the mutants, notes): each mutant a dict with id, module, file, function, overload, kind,
    line, what (the edit), and text (the mutated file)."""
    structs = struct_fields(root)
    found, notes = [], []
    mods = modules(root)
    for module, (rel, names) in sorted(mods.items()):
        if wanted_modules and module not in wanted_modules:
            continue
        with open(os.path.join(root, rel), encoding='utf-8', errors='replace') as f:
            text = f.read()
        s = blank(text)
        defs = definitions(text, s)
        defined = {name for name, _, _, _ in defs}
        for name in names:
            if name not in defined:
                continue  # named in the header, defined elsewhere (another module, a macro)
            if wanted_functions and name not in wanted_functions:
                continue
            overload = 0
            for dname, rtype, open_, close in defs:
                if dname != name:
                    continue
                base = f'{module}:{name}:{overload}'
                body = s[open_ + 1:close]
                for kind in kinds:
                    edit = None
                    if kind in ('ret0', 'ret1'):
                        if rtype == 'void':
                            value = '' if kind == 'ret0' else None
                        elif kind == 'ret0':
                            value = zero_of(rtype, structs)
                            if value is None:
                                notes.append(f'{base}:ret0 skipped: no zero constructor for {rtype}')
                        else:
                            value = ONES.get(rtype)
                        if value is not None:
                            stmt = f' return {value};'.replace('return ;', 'return;')
                            edit = (open_ + 1, '', stmt)
                    elif kind == 'cmp':
                        m = COMPARISON.search(body)
                        if m:
                            edit = (open_ + 1 + m.start(), m.group(1), FLIP[m.group(1)])
                    elif kind == 'const':
                        c = mutate_constant(body)
                        if c:
                            edit = (open_ + 1 + c[0], c[1], c[2])
                    else:
                        c = edit_of(kind, body)
                        if c:
                            edit = (open_ + 1 + c[0], c[1], c[2])
                    if edit is None:
                        continue
                    at, old, new = edit
                    line = text.count('\n', 0, at) + 1
                    mutated = text[:at] + new + text[at + len(old):]
                    what = (f'inserted `{new.strip()}`' if not old else f'removed `{old.strip()}`' if not new
                            else f'`{old}` -> `{new}`')
                    found.append({'id': f'{base}:{kind}', 'module': module, 'file': rel, 'function': name,
                                  'overload': overload, 'kind': kind, 'line': line, 'what': what,
                                  'text': mutated})
                overload += 1
    return found, notes


# ---------------------------------------------------------------- running the checks

def run_penumbra(cmd, timeout, log=None):
    """(exit code or 'timeout', output, seconds). The check runs in its own process group, killed
    whole on a timeout."""
    env = dict(os.environ)
    if log:
        env['PENUMBRA_SOURCE_LOG'] = log
    start = time.monotonic()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            errors='replace', env=env, start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=timeout)
        code = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        code = 'timeout'
    return code, out, time.monotonic() - start


def registered_checks(penumbra):
    r = subprocess.run([penumbra, 'check', 'penumbra-mutation-no-such-check'], capture_output=True, text=True)
    m = re.search(r'expected one of (.*)$', r.stderr.strip())
    if r.returncode != 2 or not m:
        raise Usage(f'cannot list the registered checks: `penumbra check <unknown>` said {r.stderr.strip()!r}')
    return [c.strip() for c in m.group(1).split(',')]


def tree_digest(root, penumbra, api):
    h = hashlib.sha256()
    for path in sorted(walk(root, ('',))):
        h.update(os.path.relpath(path, root).encode())
        with open(path, 'rb') as f:
            h.update(hashlib.sha256(f.read()).digest())
    st = os.stat(penumbra)
    h.update(f'{os.path.realpath(penumbra)} {st.st_size} {st.st_mtime_ns} {api}'.encode())
    return h.hexdigest()[:16]


def read_log(path):
    try:
        with open(path, encoding='utf-8', errors='replace') as f:
            return {line.strip() for line in f if line.strip()}
    except FileNotFoundError:
        return set()


def coverage(args, checks, work):
    """{check: {'reads': [files], 'seconds': s}}: each check run once on the unmutated root with
    the runner's source log (cached)."""
    cache = os.path.join(work, f'coverage-{args.api}-{tree_digest(args.glsl_root, args.penumbra, args.api)}.json')
    if os.path.exists(cache):
        with open(cache) as f:
            data = json.load(f)
        if sorted(data) == sorted(checks):
            return data
    data = {}
    for check in checks:
        log = os.path.join(work, f'trace-{check}.log')
        if os.path.exists(log):
            os.remove(log)
        code, out, seconds = run_penumbra(
            [args.penumbra, 'check', check, '--glsl-root', args.glsl_root, '--api', args.api], args.timeout, log)
        if code != 0:
            raise Usage(f'check {check} does not pass on the unmutated root {args.glsl_root} '
                        f'(exit {code}): mutants are measured against a passing root\n{out}')
        reads = sorted(read_log(log))
        data[check] = {'reads': reads, 'seconds': round(seconds, 2)}
        print(f'traced {check}: {len(reads)} files, {seconds:.1f} s', flush=True)
    if not any(d['reads'] for d in data.values()):
        raise Usage('the runner logged no file read into $PENUMBRA_SOURCE_LOG (a runner built before the log?)')
    with open(cache, 'w') as f:
        json.dump(data, f, indent=1, sort_keys=True)
    return data


# A module that is a part of another's (a structure's variant, a helper of one technique, a pass's
# include) has that module's check as its own.
OWN_CHECK = {'pcss_regions_mip': 'pcss_regions', 'pcss_regions_pyramid': 'pcss_regions', 'traversal_mip': 'traversal',
             'traversal_pyramid': 'traversal', 'backprojection_mask': 'backprojection', 'variance_bound': 'vsm',
             'correlated_multi_jitter': 'sample_table', 'gbuffer_receiver_plane': 'pipeline'}


def covering_checks(module, rel, checks, trace, mode, root):
    own = OWN_CHECK.get(module.split('/')[-1], module.split('/')[-1])
    if mode == 'own':
        # The module's own check, and `exports` where the module has an export entry
        # (glsl/exports/<module>.comp: the entry the exports check runs).
        cover = [own] if own in checks else []
        if 'exports' in checks and own != 'exports' and os.path.exists(os.path.join(root, 'exports', own + '.comp')):
            cover.append('exports')
        return cover
    cover = [c for c in checks if rel in trace[c]['reads']]
    cover.sort(key=lambda c: (c != own, trace[c]['seconds'], c))
    return cover


def run_mutant(args, mutant, cover, work):
    """The mutant's record: result, the check that killed it, its FAIL line, seconds."""
    tmp = tempfile.mkdtemp(prefix='mutant-', dir=work)
    record = {k: v for k, v in mutant.items() if k != 'text'}
    record['checks'] = cover
    try:
        copy = os.path.join(tmp, 'glsl')
        shutil.copytree(args.glsl_root, copy, symlinks=True)
        with open(os.path.join(copy, mutant['file']), 'w', encoding='utf-8') as f:
            f.write(mutant['text'])
        start = time.monotonic()
        log = os.path.join(tmp, 'reads.log')
        for check in cover:
            # The CTest subset runs each check on its short fixtures (`check --quick`, the broken
            # copies' rule: docs/reliability.md); every one of its mutants still fails there.
            quick = ['--quick'] if args.quick else []
            code, out, _ = run_penumbra([args.penumbra, 'check', check, '--glsl-root', copy, '--api', args.api] + quick,
                                        args.timeout, log)
            if code == 'timeout':
                record.update(result='timeout', by=check, detail=f'no verdict within {args.timeout} s')
                break
            if code == 1:
                fails = [m.group(2) for m in FAIL_LINE.finditer(out)]
                detail = fails[0] if fails else out.strip().split('\n')[-1]
                stillborn = COMPILE_ERROR.search(out) is not None
                record.update(result='stillborn' if stillborn else 'killed', by=check, detail=detail[:300])
                break
            if code != 0:
                tail = out.strip().split('\n')[-3:]
                record.update(result='error', by=check, detail=f'exit {code}: ' + ' | '.join(tail)[:300])
                break
        else:
            reads = read_log(log)
            if mutant['file'] in reads:
                record.update(result='survived', by=None, detail='every covering check passed')
            elif reads:
                record.update(result='unread', by=None, detail=f'no check run read {mutant["file"]}')
            else:
                record.update(result='survived', by=None,
                              detail='every covering check passed (the runner keeps no source log: read unknown)')
        record['seconds'] = round(time.monotonic() - start, 2)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return record


# ---------------------------------------------------------------- report

def load_equivalent(path):
    """{mutant id: reason} of the survivors explained as equivalent."""
    explained = {}
    if path and os.path.exists(path):
        with open(path, encoding='utf-8') as f:
            for line in f:
                line = line.strip()
                if line and not line.startswith('#'):
                    mid, _, reason = line.partition(' ')
                    explained[mid] = reason.strip()
    return explained


def score_table(records, api):
    by_module = {}
    for r in records:
        by_module.setdefault(r['module'], []).append(r)
    lines = [f'| module ({api}) | ' + ' | '.join(KINDS) + ' | all | timeouts | survivors |',
             '| --- |' + ' ---: |' * (len(KINDS) + 2) + ' --- |']
    totals = {k: [0, 0] for k in KINDS + ('all',)}
    timeouts_all = 0
    for module in sorted(by_module):
        rs = by_module[module]
        cells = []
        for kind in KINDS + ('all',):
            counted = [r for r in rs if (kind == 'all' or r['kind'] == kind) and r['result'] not in ('stillborn', 'equivalent')]
            killed = sum(r['result'] in ('killed', 'timeout') for r in counted)
            totals[kind][0] += killed
            totals[kind][1] += len(counted)
            cells.append(f'{killed}/{len(counted)}' if counted else '–')
        timeouts = sum(r['result'] == 'timeout' for r in rs)
        timeouts_all += timeouts
        survivors = [f'`{r["function"]}:{r["overload"]}:{r["kind"]}`' + (' (equivalent)' if r['result'] == 'equivalent' else '')
                     for r in rs if r['result'] in ('survived', 'equivalent', 'unread')]
        lines.append(f'| {module} | ' + ' | '.join(cells) + f' | {timeouts} | {", ".join(survivors) or "—"} |')
    lines.append('| **all** | ' + ' | '.join(f'{k}/{n}' for k, n in totals.values()) + f' | {timeouts_all} | |')
    return '\n'.join(lines) + '\n'


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(os.path.dirname(here))
    p = argparse.ArgumentParser(prog='mutate.py', description=__doc__.split('\n')[0])
    p.add_argument('penumbra', help='the penumbra binary')
    p.add_argument('--glsl-root', default=os.path.join(repo, 'glsl'), help='the modules to mutate (default: the repository\'s)')
    p.add_argument('--api', default='gl450', choices=('gl450', 'es310', 'vulkan', 'hlsl'))
    p.add_argument('--modules', help='comma-separated module names')
    p.add_argument('--functions', help='comma-separated public calls')
    p.add_argument('--kinds', default=','.join(KINDS), help='comma-separated of ' + ', '.join(KINDS))
    p.add_argument('--checks', choices=('traced', 'own'), default='traced',
                   help='the covering checks (traced, the default) or the module\'s own check only')
    p.add_argument('--quick', action='store_true', help='the CTest subset')
    p.add_argument('--jobs', type=int, default=1)
    p.add_argument('--timeout', type=float, default=300.0, help='seconds one check run may take (default 300)')
    p.add_argument('--work', help='scratch and trace cache (default: a directory beside the binary)')
    p.add_argument('--equivalent', default=os.path.join(here, 'equivalent.txt'))
    p.add_argument('--markdown')
    p.add_argument('--json')
    p.add_argument('--list', action='store_true', help='list the mutants, run nothing')
    args = p.parse_args(argv)

    kinds = [k for k in args.kinds.split(',') if k]
    bad = [k for k in kinds if k not in KINDS]
    if bad or not kinds:
        raise Usage(f'--kinds {args.kinds!r}: expected some of {", ".join(KINDS)}')
    if not 1 <= args.jobs <= 64:
        raise Usage(f'--jobs {args.jobs}: expected 1..64')
    if not 0.1 <= args.timeout <= 3600:
        raise Usage(f'--timeout {args.timeout}: expected 0.1..3600 seconds')
    functions = set(args.functions.split(',')) if args.functions else None
    mode = args.checks
    if args.quick:
        kinds = [k for k in kinds if k in QUICK_KINDS] if args.kinds != ','.join(KINDS) else list(QUICK_KINDS)
        if not kinds:  # issue 54 X12: it used to blame --functions
            raise Usage(f'--quick runs the return-constant mutants (ret0, ret1) and one of each of '
                        f'{", ".join(QUICK_KINDS[2:])}: --kinds {args.kinds} asks for none')
        functions = functions or set(QUICK_CALLS) | {m.split(':')[1] for m in QUICK_KIND_MUTANTS}
        mode = 'own'
    args.glsl_root = os.path.abspath(args.glsl_root)
    if not os.path.isdir(args.glsl_root):
        raise Usage(f'--glsl-root {args.glsl_root}: not a directory')

    mods = modules(args.glsl_root)
    wanted = set(args.modules.split(',')) if args.modules else None
    if wanted and wanted - set(mods):
        raise Usage(f'--modules: no module {", ".join(sorted(wanted - set(mods)))} '
                    f'(expected some of {", ".join(sorted(mods))})')
    todo, notes = mutants(args.glsl_root, wanted, functions, kinds)
    if args.quick:  # the return constants of QUICK_CALLS, the other kinds' QUICK_KIND_MUTANTS
        todo = [m for m in todo if (m['kind'] in ('ret0', 'ret1') and m['function'] in QUICK_CALLS) or
                m['id'] in QUICK_KIND_MUTANTS]
    if args.quick and args.kinds == ','.join(KINDS):
        # One return constant a definition (the suite's time): `return 1.0;` where it applies — a
        # fully lit result, the false PASS issue 39 found — else the zero.
        ones = {m['id'].rsplit(':', 1)[0] for m in todo if m['kind'] == 'ret1'}
        todo = [m for m in todo if m['kind'] == 'ret1' or m['id'].rsplit(':', 1)[0] not in ones]
    found = {m['function'] for m in todo} | {n.split(':')[1] for n in notes}
    if args.functions:
        missing = functions - found
        if missing:
            where = f' in --modules {args.modules}' if args.modules else ''
            raise Usage(f'--functions: no public definition of {", ".join(sorted(missing))}{where}')
    elif args.quick and not todo:  # its own calls: those of --modules, when given
        raise Usage(f'--quick --modules {args.modules}: none of the quick subset\'s calls ({", ".join(sorted(QUICK_CALLS))}) '
                    'is defined there')
    if args.list:
        for m in todo:
            print(f'{m["id"]}  {m["file"]}:{m["line"]}  {m["what"]}')
        for n in notes:
            print('note: ' + n)
        print(f'{len(todo)} mutants')
        return 0

    if not (os.path.isfile(args.penumbra) and os.access(args.penumbra, os.X_OK)):
        raise Usage(f'{args.penumbra}: not an executable')
    info = subprocess.run([args.penumbra, 'info', '--api', 'vulkan' if args.api in ('vulkan', 'hlsl') else args.api],
                          capture_output=True, text=True)
    if info.returncode == 3:
        print('SKIPPED: ' + info.stderr.strip())
        return 77
    if info.returncode != 0:
        raise Usage(f'penumbra info: exit {info.returncode}: {info.stderr.strip()}')
    work = os.path.abspath(args.work or os.path.join(os.path.dirname(os.path.abspath(args.penumbra)), 'mutation'))
    os.makedirs(work, exist_ok=True)

    started = time.monotonic()
    checks = registered_checks(args.penumbra)
    trace = coverage(args, checks, work) if mode == 'traced' else None
    plan, uncovered = [], []
    for m in todo:
        cover = covering_checks(m['module'], m['file'], checks, trace, mode, args.glsl_root)
        if not cover:
            uncovered.append(m['module'])
        else:
            plan.append((m, cover))
    uncovered = sorted(set(uncovered))
    for module in uncovered:
        print(f'{module}: FAIL no check covers it (no registered check {"is named as it or its family (OWN_CHECK)" if mode == "own" else "reads " + mods[module][0]})')
    print(f'{len(plan)} mutants of {len({m["module"] for m, _ in plan})} modules on {args.api}, '
          f'{args.jobs} at a time', flush=True)

    records = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_mutant, args, m, cover, work) for m, cover in plan]
        for fut in futures:
            r = fut.result()
            records.append(r)
            by = f' by {r["by"]}' if r.get('by') else ''
            print(f'{r["id"]}: {r["result"]}{by} ({r["seconds"]:.1f} s): {r["what"]}: {r["detail"]}', flush=True)

    explained = load_equivalent(args.equivalent)
    reached = reachable(args.glsl_root)
    for r in records:
        if r['result'] in ('survived', 'unread'):
            entries = sorted(reached.get(r['function'], []))
            r['reached_by'] = entries
            ran = None if trace is None else {f for c in r['checks'] for f in trace[c]['reads']}
            run = entries if ran is None else [e for e in entries if e in ran]
            if not entries:
                r['detail'] += '; no pass or export calls it: no check can see it'
            elif not run:
                r['detail'] += f'; only {", ".join(entries)} call it, which no check runs'
            else:
                r['detail'] += f'; called from {", ".join(run[:3])}{", …" if len(run) > 3 else ""}'
        if r['result'] == 'survived' and r['id'] in explained:
            r['result'] = 'equivalent'
            r['reason'] = explained[r['id']]
    wall = time.monotonic() - started
    table = score_table(records, args.api)
    print()
    print(table, end='')
    for n in notes:
        print('note: ' + n)
    for r in records:
        if r['result'] == 'equivalent':
            print(f'equivalent: {r["id"]} ({r["file"]}:{r["line"]}, {r["what"]}): {r["reason"]}')
    bad = [r for r in records if r['result'] in ('survived', 'unread', 'stillborn', 'error')]
    for r in bad:
        print(f'{r["result"].upper()}: {r["id"]} ({r["file"]}:{r["line"]}, {r["what"]}): {r["detail"]}')
    print(f'{len(records)} mutants, {sum(r["result"] in ("killed", "timeout") for r in records)} killed '
          f'({sum(r["result"] == "timeout" for r in records)} by timeout), '
          f'{sum(r["result"] == "equivalent" for r in records)} equivalent, {len(bad)} not killed, '
          f'{len(uncovered)} modules without a check; {wall:.0f} s')
    if args.markdown:
        with open(args.markdown, 'w', encoding='utf-8') as f:
            f.write(table)
    if args.json:
        with open(args.json, 'w', encoding='utf-8') as f:
            json.dump({'api': args.api, 'seconds': round(wall, 1), 'jobs': args.jobs, 'checks': mode,
                       'uncovered': uncovered, 'notes': notes, 'mutants': records}, f, indent=1)
    return 1 if bad or uncovered else 0


if __name__ == '__main__':
    try:
        sys.exit(main(sys.argv[1:]))
    except Usage as e:
        print(f'mutate.py: error: {e}', file=sys.stderr)
        sys.exit(2)
    except KeyboardInterrupt:
        sys.exit(130)
