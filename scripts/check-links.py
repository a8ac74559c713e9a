#!/usr/bin/env python3
"""Checks that every file, section and anchor that README.md and docs/**/*.md
point to exists:

- Markdown links and images, [text](path), [text](path#anchor), [text](#anchor):
  the file (relative to the linking file) and, with an anchor, a heading of
  that file whose GitHub anchor (lower case, punctuation dropped, spaces as
  hyphens) is the anchor. Links to http(s):// and mailto: are not fetched.
- Paths written in the text from the repository root (`docs/usage.md`,
  `plots/style.py`, `experiments/results/x.json.xz`): the file or folder. Paths
  with a placeholder (<name>, *, N, NAME, ...) are skipped, and a path
  written after a folder (DIR/plots/x.png, out/main/...: what a run writes)
  is not read from the root; `x.{h,cpp}` is both files.
- A section named after a file: `README "Layout"`, `README.md, "Layout"`,
  `docs/specular.md ("The LTC table")`: a heading of that file that starts with
  the quoted words; `docs/design.md section 12`: a heading numbered 12.

    python3 scripts/check-links.py [FILE.md ...]     (default: README.md and docs/**/*.md)
    python3 scripts/check-links.py --self-test       (shows that a broken link fails)

Exits 1 with one line per broken reference (FILE:LINE: what), 0 when all hold.
Code blocks (``` fences and indented blocks) are not read. Standard library only.
"""
import argparse
import glob
import os
import re
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOP = ("docs", "plots", "scripts", "experiments", "tests", "host", "kernels", "luminaires", "fuzz", "data")
LINK = re.compile(r"!?\[(?:[^\]\\]|\\.)*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
PATH = re.compile(r"(?<![\w./-])((?:" + "|".join(TOP) + r")/(?:\{[^}\s]*\}|[\w./+*<>$-])*(?<=[\w/*>}]))")
SECTION = re.compile(r"(README(?:\.md)?|(?<![\w/])docs/[\w/.-]+\.md)(?:,? \(?|, )\"([^\"]+)\"")
NUMBERED = re.compile(r"((?<![\w/])docs/[\w/.-]+\.md),? sections? (\d+)")
PLACEHOLDER = re.compile(r"[<>*{}$]|\bN\b|\.\.\.|(?<![a-z])(?!README)[A-Z]{3,}(?![a-z])|X+\.")


def slug(heading):
    """GitHub's anchor of a heading: lower case, markup and punctuation dropped, spaces as hyphens."""
    s = re.sub(r"[`*_]|\[|\]\([^)]*\)", "", heading.strip()).lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def text_lines(path):
    """(line number, line) of the file outside code blocks."""
    out, fence = [], False
    with open(path, encoding="utf-8") as f:
        for i, line in enumerate(f, 1):
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            if fence or line.startswith("    ") or line.startswith("\t"):
                continue
            out.append((i, line.rstrip("\n")))
    return out


_headings = {}


def headings(path, bold=True):
    """The headings of a Markdown file, as written (without the #s), and
    the bold run-in headings that open a paragraph (**Results as a table.**)."""
    key = (path, bold)
    if key not in _headings:
        hs = []
        if path.endswith(".md") and os.path.isfile(path):
            for _, line in text_lines(path):
                m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line) or (bold and re.match(r"\*\*([^*]+?)\.?\*\*", line))
                if m:
                    hs.append(m.group(1))
        _headings[key] = hs
    return _headings[key]


def anchors(path):
    out, seen = set(), {}
    for h in headings(path, bold=False):
        s = slug(h)
        k = seen.get(s, 0)
        out.add(s if k == 0 else "{}-{}".format(s, k))
        seen[s] = k + 1
    return out


def rel(path):
    return os.path.relpath(path, ROOT)


def check_link(src, target):
    if re.match(r"[a-z]+:", target):  # http:, https:, mailto:
        return None
    path, _, anchor = target.partition("#")
    dest = os.path.normpath(os.path.join(os.path.dirname(src), path)) if path else src
    if not os.path.exists(dest):
        return "link to {}: no such file".format(target)
    if anchor and dest.endswith(".md") and anchor not in anchors(dest):
        return "link to {}: {} has no heading with anchor #{}".format(target, rel(dest), anchor)
    return None


def check_path(p, root):
    """A path from the repository root; one {a,b} group is read as both paths."""
    p = p.rstrip(".")
    m = re.search(r"\{([^{}]*)\}", p)
    if m:
        return next((e for e in (check_path(p[:m.start()] + alt + p[m.end():], root)
                                 for alt in m.group(1).split(",")) if e), None)
    if PLACEHOLDER.search(p):
        return None
    return None if os.path.exists(os.path.join(root, p)) else "{}: no such file or folder".format(p)


def section_file(name, root):
    return os.path.join(root, "README.md") if name.startswith("README") else os.path.join(root, name)


def check_section(name, title, root):
    f = section_file(name, root)
    if not os.path.exists(f):
        return "{}: no such file".format(name)
    want = title.lower().rstrip(".")
    if any(h.lower().startswith(want) or slug(h) == slug(title) for h in headings(f)):
        return None
    return '{} "{}": no such section'.format(name, title)


def check_numbered(name, number, root):
    f = section_file(name, root)
    if not os.path.exists(f):
        return "{}: no such file".format(name)
    if any(re.match(r"{}\b".format(number), h) for h in headings(f)):
        return None
    return "{} section {}: no heading numbered {}".format(name, number, number)


def check_file(path, root=ROOT):
    problems = []
    for n, line in text_lines(path):
        found = [check_link(path, m.group(1)) for m in LINK.finditer(line)]
        bare = LINK.sub(" ", re.sub(r"https?://\S+", " ", line))
        found += [check_path(m.group(1), root) for m in PATH.finditer(bare)]
        found += [check_section(m.group(1), m.group(2), root) for m in SECTION.finditer(line)]
        found += [check_numbered(m.group(1), m.group(2), root) for m in NUMBERED.finditer(line)]
        problems += ["{}:{}: {}".format(rel(path), n, p) for p in found if p]
    return problems


def default_files(root=ROOT):
    return [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"),
                                                                recursive=True))


def self_test():
    """A small tree with one good and one broken reference of each kind: the
    good ones pass, each broken one is reported."""
    d = tempfile.mkdtemp()
    try:
        os.makedirs(os.path.join(d, "docs", "studies"))
        with open(os.path.join(d, "docs", "ref.md"), "w") as f:
            f.write("# Ref\n\n## 3. Third part\n\n## The table\n")
        good = ("[a](ref.md) [b](ref.md#the-table) [c](#good) docs/ref.md, docs/ref.md (\"The table\"), "
                "docs/ref.md section 3, README \"Top\", docs/<name>.md, docs/{ref,good}.md, out/main/docs/x.md\n")
        bad = ("[a](gone.md)\n[b](ref.md#no-such)\n[c](#nowhere)\ndocs/gone.md\ndocs/ref.md (\"No such\")\n"
               "docs/ref.md section 9\nREADME \"Performance\"\ndocs/{ref,gone2}.md\n")
        with open(os.path.join(d, "README.md"), "w") as f:
            f.write("# Top\n")
        with open(os.path.join(d, "docs", "good.md"), "w") as f:
            f.write("# Good\n\n" + good + "\n    docs/in-a-code-block.md\n```\n[x](gone.md)\n```\n")
        with open(os.path.join(d, "docs", "bad.md"), "w") as f:
            f.write("# Top\n\n" + bad)
        global ROOT
        root, ROOT = ROOT, d
        try:
            ok_good = check_file(os.path.join(d, "docs", "good.md"), d)
            found = check_file(os.path.join(d, "docs", "bad.md"), d)
        finally:
            ROOT = root
    finally:
        shutil.rmtree(d)
    want = ["gone.md: no such file", "#no-such", "#nowhere", "docs/gone.md: no such file", '"No such": no such',
            "section 9", '"Performance": no such', "docs/gone2.md: no such"]
    missed = [w for w in want if not any(w in p for p in found)]
    fails = []
    if ok_good:
        fails.append("good references reported: {}".format(ok_good))
    if missed or len(found) != len(want):
        fails.append("broken references missed {} (found {})".format(missed, found))
    print("check-links self-test: " + ("passes" if not fails else "FAILS: " + "; ".join(fails)))
    return 1 if fails else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="*")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    files = [os.path.abspath(f) for f in a.files] or default_files()
    problems = [p for f in files for p in check_file(f)]
    print("\n".join(problems) if problems else "check-links: {} files, every link holds".format(len(files)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
