#!/usr/bin/env python3
"""Holds the rule that a method is looked up by name once, by the SPEC parser:
    scripts/family-lookup.py [--self-test] FILE...
e.g. scripts/family-lookup.py $(git ls-files 'host/*.cpp' 'host/*.h')
A lookup is a call of lb::methods::family(name, kind): `family(` with
arguments, not after '.' or '->' (a member such as MethodSpec::family()) and
not a declaration (after a type: `Family& family(`, `void family(`). Comments
and strings are not read (scripts/long-functions.py's strip). Only the
registry (host/methods/registry.{h,cpp}, which defines it) and the parser
(host/methods/spec.cpp, parseSpec) may call it; everything else takes the
MethodSpec parseSpec returns and reads its family(). --self-test checks the
checker on made-up sources (a call must fail, a member, a declaration and a
comment must pass). Exit code 0, or 1 on any lookup outside them (CI runs it
on host/: scripts/run-tests.sh)."""
import importlib.util, pathlib, re, sys

_here = pathlib.Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location('long_functions', _here / 'long-functions.py')
_lf = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_lf)

ALLOWED = {'host/methods/registry.h', 'host/methods/registry.cpp', 'host/methods/spec.cpp'}
# `family(` with an argument, not a member access and not after a type name.
CALL = re.compile(r'(?<![\w.>])family\(\s*(?!\))')
DECLARED = re.compile(r'(\bvoid|&|\*|\bFamily)\s*$')


def lookups(src):
    """(line, text) of each lookup in the source text."""
    code = _lf.strip(src)
    out = []
    for m in CALL.finditer(code):
        before = code[:m.start()]
        if DECLARED.search(before.split('\n')[-1]):
            continue
        line = before.count('\n') + 1
        out.append((line, src.split('\n')[line - 1].strip()))
    return out


def self_test():
    cases = [
        ('const Family& f = family(s.name, kind);', 1),
        ('x = methods::family("mc").params;', 1),
        ('x = lb::methods::family(\n  name);', 1),
        ('const Family& f = spec.family();', 0),
        ('auto& f = p->family();', 0),
        ('const Family& family() const { return fam_; }', 0),
        ('const Family& family(const std::string& name, SceneKind kind);', 0),
        ('void family(const methods::Family& f, int x) const', 0),
        ('run.family(*f, ref);', 0),
        ('// methods::family(name, kind)', 0),
        ('std::string s = "family(x)";', 0),
    ]
    bad = 0
    for src, want in cases:
        got = len(lookups(src))
        if got != want:
            print(f'family-lookup --self-test: {src!r}: {got} lookups, expected {want}')
            bad += 1
    print(f'family-lookup --self-test: {len(cases) - bad} of {len(cases)} cases as expected')
    return 1 if bad else 0


def main(argv):
    if argv[:1] == ['--self-test']:
        return self_test()
    found = 0
    for path in argv:
        rel = pathlib.Path(path).as_posix()
        if rel in ALLOWED:
            continue
        for line, text in lookups(pathlib.Path(path).read_text()):
            print(f'{rel}:{line}: a method looked up by name outside the parser: {text}\n'
                  '  expected: the MethodSpec parseSpec returned (spec.family()), not methods::family(name)')
            found += 1
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
