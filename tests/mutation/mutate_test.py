#!/usr/bin/env python3
"""mutate_test.py GLSL_ROOT: mutate.py's sites and edits, without a GL context (CTest mutation_sites).

- on the library: every technique's one-call is a site with each overload (pnPoissonPcss,
  pnVogelPcss, pnFastPcss, pnPcf, pnExactPcss, pnHqepcss, pnBackprojection: two definitions each;
  pnSavsm, pnVsm, pnEvsm2, pnEvsm4), struct lines are not, and every return-constant mutant
  is inserted after its body's `{` on the same line (diagnostics keep their line numbers);
- on a made-up module: a function added to the use: header is a site without a change to the
  tool; the comparison flip skips comments, preprocessor lines and shifts; issue 54's kinds (swap,
  bound, bound1, minmax, offset, drop) each edit their first site; the constant change
  takes the first float literal (0 -> 0.5, x -> 1.5 x), else the first integer + 1; a struct
  result gets its constructor of zeros; a function defined only in an #if branch is a site.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutate  # noqa: E402

FAILURES = []


def expect(cond, what):
    if not cond:
        FAILURES.append(what)
        print('FAIL: ' + what)


MODULE = '''// made_up.glsl — a module the tool has never seen.
//
// use:
//   float pnMadeUp(float x, float y)
//   PnMadeUpResult pnMadeUpResult(int n)
//   bool pnMadeUpFlag(int n)     (pnMadeUpHelper is not defined here: no site)
//   vec2 pnMadeUpKinds(sampler2D s, ivec2 p, float a, float b)
//   PnMadeUpResult { float a; ivec2 b; bool c; PnMadeUpInner inner; }
//
// cost: nothing.

#ifndef MADE_UP
#define MADE_UP 1 < 2

struct PnMadeUpInner { uvec3 q; float w[2]; };
struct PnMadeUpResult { float a; ivec2 b; bool c; PnMadeUpInner inner; };

float pnMadeUp(float x, float y) {
  // a comment with < and 2.0
  int s = 1 << 3;
#if MADE_UP > 0
  s = s >> 1;
#endif
  return x <= y ? 0.0 : 2.5;
}

float pnMadeUp(float x) { return pnMadeUp(x, 0.0); }

PnMadeUpResult pnMadeUpResult(int n) {
  return PnMadeUpResult(float(n + 7), ivec2(n), n != 0, PnMadeUpInner(uvec3(0u), float[2](0.0, 0.0)));
}

vec2 pnMadeUpKinds(sampler2D s, ivec2 p, float a, float b) {
  vec2 sum = vec2(0.0);
  for (int i = 0; i < 2 * 4; ++i) sum += texelFetch(s, p, 0).xy + vec2(min(a, b));
  return sum * (a - b) + floor(a);
}

#ifdef PN_MADE_UP_OPTION
bool pnMadeUpFlag(int n) { return n == 0x1F; }
#else
bool pnMadeUpFlag(int n) { return n >= 3u; }
#endif
#endif
'''


def main():
    root = os.path.abspath(sys.argv[1])
    found, notes = mutate.mutants(root)
    ids = {m['id'] for m in found}
    for call, overloads in [('poisson_pcss:pnPoissonPcss', 2), ('vogel_pcss:pnVogelPcss', 2), ('fast_pcss:pnFastPcss', 2),
                            ('pcf:pnPcf', 2), ('exact_pcss:pnExactPcss', 2), ('hqepcss:pnHqepcss', 2),
                            ('savsm:pnSavsm', 1), ('vsm:pnVsm', 1), ('vsm:pnEvsm2', 1), ('vsm:pnEvsm4', 1),
                            ('backprojection:pnBackprojection', 2)]:
        for k in range(overloads):
            for kind in ('ret0', 'ret1'):
                expect(f'{call}:{k}:{kind}' in ids, f'no mutant {call}:{k}:{kind}')
        expect(f'{call}:{overloads}:ret0' not in ids, f'{call}: more than {overloads} definitions')
    expect(not any(m['function'] in ('PnLight', 'PnPcf') for m in found), 'a struct line became a site')
    for m in found:
        if m['kind'] in ('ret0', 'ret1'):
            with open(os.path.join(root, m['file']), encoding='utf-8') as f:
                original = f.read().split('\n')
            line = m['text'].split('\n')[m['line'] - 1]
            expect(len(m['text'].split('\n')) == len(original), f'{m["id"]}: the mutant moved lines')
            expect('{ return' in line, f'{m["id"]}: the return is not after the body\'s brace: {line!r}')

    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, 'made_up.glsl'), 'w', encoding='utf-8') as f:
            f.write(MODULE)
        found, notes = mutate.mutants(tmp)
        got = {m['id']: m for m in found}
        print('\n'.join(f'{m["id"]}: line {m["line"]}: {m["what"]}' for m in found))
        want = {
            'made_up:pnMadeUp:0:ret0': 'inserted `return 0.0;`',
            'made_up:pnMadeUp:0:ret1': 'inserted `return 1.0;`',
            'made_up:pnMadeUp:0:cmp': '`<=` -> `>`',
            'made_up:pnMadeUp:0:const': '`0.0` -> `0.5`',
            'made_up:pnMadeUp:1:const': '`0.0` -> `0.5`',
            'made_up:pnMadeUpResult:0:ret0':
                'inserted `return PnMadeUpResult(0.0, ivec2(0), false, PnMadeUpInner(uvec3(0u), float[2](0.0, 0.0)));`',
            'made_up:pnMadeUpResult:0:cmp': '`!=` -> `==`',
            'made_up:pnMadeUpResult:0:const': '`0.0` -> `0.5`',  # a float literal first
            'made_up:pnMadeUpFlag:0:ret1': 'inserted `return true;`',
            'made_up:pnMadeUpFlag:0:const': '`0x1F` -> `0x20`',
            'made_up:pnMadeUpFlag:1:cmp': '`>=` -> `<`',
            'made_up:pnMadeUpFlag:1:const': '`3u` -> `4u`',
            # Issue 54's kinds, each on its body's first site.
            'made_up:pnMadeUpKinds:0:swap': '`xy` -> `yx`',
            'made_up:pnMadeUpKinds:0:bound': '`2 * 4` -> `(2 * 4) / 2`',
            'made_up:pnMadeUpKinds:0:bound1': '`2 * 4` -> `(2 * 4) - 1`',
            'made_up:pnMadeUpKinds:0:minmax': '`min` -> `max`',
            'made_up:pnMadeUpKinds:0:offset': '`p` -> `(p) + 1`',
            'made_up:pnMadeUpKinds:0:drop': 'removed `+ vec2(min(a, b))`',
            'made_up:pnMadeUp:0:swap': None,  # `x <= y`: no swizzle, no `-` or `/`
            'made_up:pnMadeUpResult:0:drop': 'removed `+ 7`',
        }
        for mid, what in want.items():
            if what is None:
                expect(mid not in got, f'{mid}: expected no mutant, got {got.get(mid, {}).get("what")}')
                continue
            expect(mid in got and got[mid]['what'] == what,
                   f'{mid}: expected {what}, got {got[mid]["what"] if mid in got else "no mutant"}')
        expect('made_up:pnMadeUp:1:cmp' not in got, 'a comparison found in a body without one')
        expect('made_up:pnMadeUpResult:0:ret1' not in got, 'ret1 of a struct result')
        expect(not any(m['function'] == 'pnMadeUpHelper' for m in found), 'a name the module does not define')
        expect(got.get('made_up:pnMadeUp:0:cmp', {}).get('line') == 24, 'the flip is not on the return line')
    print(f'{len(FAILURES)} failures')
    return 1 if FAILURES else 0


if __name__ == '__main__':
    sys.exit(main())
