#!/usr/bin/env python3
"""Holds the OpenCL kernel code to the function limits:
    scripts/kernel-limits.py [--allow FILE] [--lines N] [--params N] [--list] FILE...
e.g. scripts/kernel-limits.py $(git ls-files 'kernels/*.h' 'kernels/*.inc' 'kernels/*.cl')
A function is a body '{' at file scope (LB_FN, LB_FN_INLINE, __kernel or a
macro such as LB_RENDER_KERNEL that opens one); LB_VFN(name) counts as name. Its
lines are counted from the '{' to the '}' (as scripts/long-functions.py), its
parameters are the top-level commas of its parameter list plus one (none for
'()' or '(void)'). A function may have at most --lines (80) lines and, unless
it is a __kernel entry point (its arguments are the host's binding
convention), at most --params (8) parameters.
The allow-list (default scripts/kernel-limits-allow.txt) holds today's
exceptions, one per line: 'FILE NAME lines|params N' (N the largest value
allowed; '#' starts a comment). It may only shrink: a function over a limit
and not listed, or over its listed value, fails; so does a listed entry that
no longer needs its value (lower it, or remove the line). --list prints every
exception in the allow-list's format; --self-test checks the checker on
made-up sources (each rule must fail and pass where it should). Exit code 0,
or 1 on any failure (CI runs both on kernels/: scripts/run-tests.sh)."""
import argparse, importlib.util, pathlib, re, subprocess, sys, tempfile

_here = pathlib.Path(__file__).resolve().parent
_spec = importlib.util.spec_from_file_location('long_functions', _here / 'long-functions.py')
_lf = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_lf)


def blank_preprocessor(s):
    """Blanks preprocessor lines (with their continuations), keeping newlines.
    Returns the blanked text and the conditionals' (offset, kind) in order,
    kind 'if' (#if, #ifdef, #ifndef), 'else' (#elif, #else) or 'endif'."""
    out, cont, conds, pos = [], False, [], 0
    for line in s.split('\n'):
        directive = cont or line.lstrip().startswith('#')
        if directive and not cont:
            word = re.match(r'\s*#\s*(\w*)', line).group(1)
            kind = {'if': 'if', 'ifdef': 'if', 'ifndef': 'if', 'elif': 'else', 'else': 'else',
                    'endif': 'endif'}.get(word)
            if kind:
                conds.append((pos, kind))
        cont = directive and line.rstrip().endswith('\\')
        out.append(' ' * len(line) if directive else line)
        pos += len(line) + 1
    return '\n'.join(out), conds


def param_count(head):
    """Parameters of the last balanced '(...)' in head (the signature before '{')."""
    q = head.rstrip()
    if not q.endswith(')'):
        return None, q
    depth = 0
    for i in range(len(q) - 1, -1, -1):
        depth += {')': 1, '(': -1}.get(q[i], 0)
        if depth == 0:
            inner = q[i + 1:-1].strip()
            break
    else:
        return None, q
    if inner in ('', 'void'):
        return 0, q[:i]
    depth, n = 0, 1
    for c in inner:
        depth += {'(': 1, '[': 1, ')': -1, ']': -1}.get(c, 0)
        n += c == ',' and depth == 0
    return n, q[:i]


def functions(path):
    """(name, first line, lines, params, is_kernel) of each function in path.
    Each branch of an #if / #elif / #else starts from the brace depth before
    the #if, so a function defined in each branch counts once per branch;
    after the #endif the count goes on from the end of the first branch."""
    s, conds = blank_preprocessor(_lf.strip(pathlib.Path(path).read_text()))
    events = sorted([(p, k) for p, k in conds] + [(m.start(), m.group()) for m in re.finditer(r'[{}]', s)])
    depth, rows, start, stack = 0, [], None, []
    for p, what in events:
        if what == 'if':
            stack.append([(depth, start), None])
        elif what in ('else', 'endif') and stack:
            entry, first = stack[-1]
            if first is None:
                stack[-1][1] = first = (depth, start)
            depth, start = entry if what == 'else' else first
            if what == 'endif':
                stack.pop()
        elif what == '{':
            if depth == 0:
                head = s[max(0, p - 3000):p]
                tail = head.rstrip()
                body = not re.search(r'(=|\b(struct|union|enum)\b[^;{}()]*)$', tail)
                start = (p, head) if body else None
            depth += 1
        elif what == '}':
            depth -= 1
            if depth == 0 and start is not None:
                rows.append(_function_row(s, start, p))
                start = None
    return rows


def _function_row(s, start, p):
    """The row of functions() for the body opened at start = (offset, head) and closed at p."""
    q, head = start
    n, before = param_count(head)
    name = re.sub(r'LB_VFN\((\w+)\)', r'\1', before)
    mm = re.search(r'(\w+)\s*$', name)
    if n is None:  # a macro that opens a kernel, e.g. LB_RENDER_KERNEL
        mm = re.search(r'(\w+)\s*$', head)
    kernel = '__kernel' in head[head.rfind(';') + 1:] or n is None
    first = s.count('\n', 0, q) + 1
    lines = s.count('\n', 0, p) + 1 - first + 1
    return (mm.group(1) if mm else '?', first, lines, n or 0, kernel)


def exceptions(files, max_lines, max_params):
    """{(file, name, 'lines'|'params'): (largest value, first line)} over the limits."""
    found = {}
    for f in files:
        for name, line, lines, params, kernel in functions(f):
            for what, v, lim in (('lines', lines, max_lines), ('params', 0 if kernel else params, max_params)):
                key = (f, name, what)
                if v > lim and v > found.get(key, (0, 0))[0]:
                    found[key] = (v, line)
    return found


def read_allow(path):
    allow = {}
    for k, line in enumerate(pathlib.Path(path).read_text().splitlines(), 1):
        line = line.split('#', 1)[0].split()
        if not line:
            continue
        if len(line) != 4 or line[2] not in ('lines', 'params') or not line[3].isdigit():
            sys.exit(f'{path}:{k}: expected "FILE NAME lines|params N", got {" ".join(line)!r}')
        allow[(line[0], line[1], line[2])] = int(line[3])
    return allow


def self_test():
    """Runs this script on made-up kernels: a function of 81 lines, a helper
    of 9 parameters, a __kernel of 9 (allowed), LB_VFN names, macro-opened
    kernels, struct bodies and initializers (not functions), a kernel in each
    branch of an #if / #else (the first with an #if that opens a brace in
    each of its own branches: 81 lines; the second 83; a function after the
    #endif of 80), and an allow-list that must only shrink."""
    body = lambda n: '{\n' + '    x += 1;\n' * (n - 2) + '}\n'
    src = ('typedef struct {\n    int a, b;\n} s_t;\nconstant int k[2] = {1, 2};\n'
           '#define MK __kernel void render(int a)\n'
           'LB_FN int LB_VFN(ok80)(int a)\n' + body(80) + 'LB_FN int long81(int a)\n' + body(81) +
           'LB_FN_INLINE int LB_VFN(p9)(int a, int b, int c, int d, int e, int f, int g, int h, int (*i)[3])\n' + body(3) +
           '__kernel void k9(int a, int b, int c, int d, int e, int f, int g, int h, int i)\n' + body(3) +
           'MK\n' + body(82) +
           '#ifdef A\n__kernel void twin(int a)\n{\n#ifdef B\n    if (a) {\n#else\n    {\n#endif\n' +
           '    x += 1;\n' * 73 + '    }\n}\n#else\n__kernel void twin(int a)\n' + body(83) + '#endif\n' +
           'LB_FN int after80(int a)\n' + body(80))
    ok = 'x.inc long81 lines 81\nx.inc p9 params 9\nx.inc MK lines 82\n'
    cases = [  # allow-list, expected exit code
        ('', 1),
        (ok + 'x.inc twin lines 83\n', 0),
        ('x.inc long81 lines 80\nx.inc p9 params 9\nx.inc MK lines 82\nx.inc twin lines 83\n', 1),  # grew
        ('x.inc long81 lines 82\nx.inc p9 params 9\nx.inc MK lines 82\nx.inc twin lines 83\n', 1),  # stale
        (ok + 'x.inc twin lines 83\nx.inc ok80 lines 81\n', 1),
        ('x.inc long81 lines 81\nx.inc MK lines 82\nx.inc twin lines 83\n', 1),  # p9 not listed
        (ok, 1),  # the #else branch's twin (83 lines) not listed
        (ok + 'x.inc twin lines 82\n', 1),  # the larger twin is the #else branch's 83
        (ok + 'x.inc twin lines 83\nx.inc after80 lines 81\n', 1),  # after the #endif: 80 lines, stale
    ]
    with tempfile.TemporaryDirectory() as d:
        pathlib.Path(d, 'x.inc').write_text(src)
        for k, (allow, want) in enumerate(cases):
            pathlib.Path(d, 'allow.txt').write_text(allow)
            rc = subprocess.run([sys.executable, __file__, '--allow', 'allow.txt', 'x.inc'], cwd=d,
                                capture_output=True).returncode
            if rc != want:
                sys.exit(f'kernel-limits self-test: case {k} exited {rc}, expected {want}')
    print('kernel-limits self-test: ok')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--allow', default=str(_here / 'kernel-limits-allow.txt'))
    ap.add_argument('--lines', type=int, default=80)
    ap.add_argument('--params', type=int, default=8)
    ap.add_argument('--list', action='store_true')
    ap.add_argument('--self-test', action='store_true')
    ap.add_argument('files', nargs='*')
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    found = exceptions(a.files, a.lines, a.params)
    if a.list:
        for (f, name, what), (v, _) in sorted(found.items()):
            print(f'{f} {name} {what} {v}')
        return
    allow = read_allow(a.allow) if pathlib.Path(a.allow).exists() else {}
    bad = []
    for key, (v, line) in sorted(found.items()):
        f, name, what = key
        lim = a.lines if what == 'lines' else a.params
        if key not in allow:
            bad.append(f'{f}:{line}: {name} has {v} {what} (limit {lim}); split it')
        elif v > allow[key]:
            bad.append(f'{f}:{line}: {name} has {v} {what}, more than its allowed {allow[key]}; the allow-list only shrinks')
    checked = set(a.files)
    for key, v in sorted(allow.items()):
        if key[0] in checked and found.get(key, (0, 0))[0] < v:
            now = found.get(key, (0, 0))[0]
            bad.append(f'{a.allow}: {" ".join(key)} {v} but now {now or "within the limit"}; '
                       f'{"lower it to " + str(now) if now else "remove the line"}')
    for b in bad:
        print(b, file=sys.stderr)
    if bad:
        print(f'kernel-limits: {len(bad)} failure(s)', file=sys.stderr)
        sys.exit(1)


if __name__ == '__main__':
    main()
