#!/usr/bin/env python3
"""List C++ functions (and lambdas) longer than LIMIT lines, longest first:
    scripts/long-functions.py [--check] LIMIT FILE...   e.g. 80 host/*/*.cpp host/*/*.h
A brace counter over comment- and string-stripped source: a '{' opens a
function body when the code before it ends with ')' plus optional qualifiers
and its enclosing scope is a namespace, a class or the file; a lambda when ']'
or '](...)' comes before it, at any depth. Lines are counted from the body's
'{' to its '}'. Exit code 0, or with --check 1 when any function is longer
(CI runs it so on host/: scripts/run-tests.sh)."""
import re, sys, pathlib

def strip(src):
    out, i, n = [], 0, len(src)
    while i < n:
        c = src[i]
        if src.startswith('//', i):
            j = src.find('\n', i); j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif src.startswith('/*', i):
            j = src.find('*/', i + 2); j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', src[i:j])); i = j
        elif src.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', src[i:])
            end = src.find(')' + m.group(1) + '"', i) + len(m.group(1)) + 2
            out.append(re.sub(r'[^\n]', ' ', src[i:end])); i = end
        elif c in '"\'':
            j = i + 1
            while j < n and src[j] != c:
                j += 2 if src[j] == '\\' else 1
            out.append(c + ' ' * (j - i - 1) + c); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)

QUAL = r'(\s*(const|override|noexcept|final|mutable|->\s*[\w:<>,\s\*&]+))*\s*$'
def main():
    args = sys.argv[1:]
    check = bool(args) and args[0] == '--check'
    args = args[1:] if check else args
    limit = int(args[0]); files = args[1:]
    rows = []
    for f in files:
        s = strip(pathlib.Path(f).read_text())
        stack = []  # (kind, pos, name)
        for m in re.finditer(r'[{}]', s):
            p = m.start()
            if s[p] == '{':
                before = s[max(0, p - 400):p]
                enclosing = [k for k, *_ in stack]
                kind = 'block'
                if re.search(r'\)' + QUAL, before) or re.search(r'\)\s*:\s*[\w:]+[({][^;]*[)}]\s*$', before):
                    if re.search(r'\]\s*(\([^()]*(\([^()]*\)[^()]*)*\))?' + QUAL, before):
                        kind = 'lambda'
                    elif all(k in ('ns', 'class') for k in enclosing):
                        kind = 'fn'
                elif re.search(r'\]\s*$', before):
                    kind = 'lambda'
                elif re.search(r'\b(namespace\s*[\w:]*|extern\s*"\s*")\s*$', before):
                    kind = 'ns'
                elif re.search(r'\b(class|struct|union)\s+\w+[^;{}()]*$', before):
                    kind = 'class'
                # name: identifier before the matching '('
                name = ''
                if kind == 'fn':
                    head = s[max(0, p - 2000):p]
                    depth = 0
                    for q in range(len(head) - 1, -1, -1):
                        if head[q] == ')': depth += 1
                        elif head[q] == '(':
                            depth -= 1
                            if depth == 0:
                                mm = re.search(r'([~\w:]+|operator\S+)\s*$', head[:q])
                                if mm and mm.group(1) not in ('if', 'for', 'while', 'switch'):
                                    name = mm.group(1)
                                    break
                stack.append((kind, p, name))
            else:
                kind, q, name = stack.pop()
                if kind in ('fn', 'lambda'):
                    start = s.count('\n', 0, q) + 1
                    # count from the signature line: the line of the name
                    end = s.count('\n', 0, p) + 1
                    n = end - start + 1
                    if n > limit:
                        rows.append((n, f, start, kind, name))
    for n, f, line, kind, name in sorted(rows, reverse=True):
        print(f'{n:4d}  {f}:{line}  {kind} {name}')
    if check and rows:
        print(f'long-functions: {len(rows)} function(s) over {limit} lines; split them', file=sys.stderr)
        sys.exit(1)
if __name__ == '__main__':
    main()
