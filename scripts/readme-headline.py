#!/usr/bin/python3
"""The README's headline, made from the main job's results: a sentence and a
table of the equal-time verdicts of every method against every Monte Carlo
baseline, with the run's commit, date and device, written between the
markers `<!-- headline:begin -->` and `<!-- headline:end -->` of README.md,
and its picture (NMSE against time, geometric mean over the scenes, every
baseline's curve: plots/error_time.py) as docs/figures/main-nmse-time.png.

    /usr/bin/python3 scripts/readme-headline.py out/main/results.json
        copies the results to experiments/results/main.json.xz (the file the
        README then cites and the check reads), writes the headline and the
        picture from them
    python3 scripts/readme-headline.py --check [RESULTS]
        exits 1 where the README's headline is not the one RESULTS (default
        experiments/results/main.json.xz) gives; no matplotlib needed
    python3 scripts/readme-headline.py --self-test
        shows that --check fails on a headline that differs from its results

The headline's last sentence states the verdicts against a denoised Monte
Carlo, from the committed results of
experiments/mc-baselines/strong-gauss-subpixel.json and
strong-atrous-subpixel.json (FILTER_RESULTS below: MC below one sample per
pixel where N = 1 is slower than the method), tallied by
experiments/mc-baselines/filter_verdicts.py: wins / ties / losses among the
pairs on time, in NMSE and in FLIP, the pairs off time (those at the floor
apart) and the pairs whose MC ran below one sample per pixel. --check and
--self-test read those files too.

A verdict is a win where the method's NMSE (its 95 % interval over seeds,
where it has one) lies wholly below the baseline's interval at equal time, a
loss where wholly above, a tie where they overlap; a pair whose times differ
by more than the run's tolerance is off-time, counted apart and never a win,
tie or loss (plots/results_io.py, pair_verdict). A record's own `verdict`
is taken where the run wrote one.
"""
import argparse
import collections
import math
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "plots"))
sys.path.insert(0, os.path.join(ROOT, "experiments", "mc-baselines"))
import filter_verdicts  # noqa: E402
from results_io import (baseline_of, baselines, equal_time, is_partner, load_context, load_records,  # noqa: E402
                        pair_verdict, written_spec)

BEGIN, END = "<!-- headline:begin -->", "<!-- headline:end -->"
RESULTS = "experiments/results/main.json.xz"
FIGURE = "docs/figures/main-nmse-time.png"
VERDICTS = ("win", "tie", "loss", "off-time")
# the filter-verdict runs the headline's last sentence states: (baseline's name, committed results)
FILTER_RESULTS = (("strong MC + Gaussian",
                   "experiments/results/mc-baselines-strong-gauss-subpixel-seeds8-pocl.json.xz"),
                  ("strong MC + a-trous",
                   "experiments/results/mc-baselines-strong-atrous-subpixel-seeds8-pocl.json.xz"))
# the methods it names, in this order, as the sentence names them
FILTER_METHODS = (("robust", "robust"), ("tuned", "tuned"), ("cubature", "the fan"))


def scene_key(r):
    return r.get("scene") or (r.get("luminaire"), r.get("height"), r.get("rotation"), r.get("precision"))


def tally(records, known):
    """{(method spec, baseline label): Counter of verdicts}, the methods in the
    order first met, and {(method, label): [method NMSE / partner NMSE]}."""
    methods = {}
    for r in records:
        if r.get("role", "method") == "method" and not is_partner(r):
            methods[(scene_key(r), written_spec(r))] = r
    counts = collections.defaultdict(collections.Counter)
    ratios = collections.defaultdict(list)
    for p in records:
        if not is_partner(p):
            continue
        label = (equal_time(p) or {}).get("label")
        m = methods.get((scene_key(p), label))
        if m is None:
            continue
        b = baseline_of(p, known)[0]
        v = pair_verdict(m, p)
        counts[(label, b)][v] += 1
        if v in ("win", "tie", "loss") and (m.get("nmse") or 0) > 0 and (p.get("nmse") or 0) > 0:
            ratios[(label, b)].append(m["nmse"] / p["nmse"])
    order = []
    for _, spec in methods:
        if spec not in order and any(k[0] == spec for k in counts):
            order.append(spec)
    return counts, order, ratios


def cell(c):
    text = "{} / {} / {}".format(c["win"], c["tie"], c["loss"])
    if c["off-time"]:
        text += " ({} off-time)".format(c["off-time"])
    other = sum(v for k, v in c.items() if k not in VERDICTS)
    if other:
        text += " ({} n/a)".format(other)
    return text


def headline(records, context, source):
    """The README's headline block (without the markers)."""
    known = baselines(records, context)
    counts, order, ratios = tally(records, known)
    if not counts:
        raise ValueError("{}: no equal-time pairs, no headline".format(source))
    labels = list(known.values())
    devices = sorted({r.get("device") for r in records if r.get("device")}) or [context.get("device", "?")]
    res = sorted({r.get("res") for r in records if r.get("res")})
    tres = sorted({(r.get("time_ms") or {}).get("res") for r in records} - {None})
    n_scenes = len({scene_key(r) for r in records if r.get("role", "method") == "method"})
    commit = (context.get("commit") or "?")[:7] + (" (modified)" if context.get("commit_dirty") else "")
    date = (context.get("date") or "?")[:10]
    # the strongest baseline, as the report names it (report_verdicts.cpp, strongestBaseline): of those
    # with at least half as many pairs at equal time as the most, the one whose NMSE the methods' comes
    # closest to (the largest mean log of NMSE method / NMSE baseline); the best method against it
    timed = {b: sum(counts[(m, b)][v] for m in order for v in ("win", "tie", "loss")) for b in labels}
    logs = {b: [math.log(x) for m in order for x in ratios[(m, b)]] for b in labels}
    most = max(timed.values())
    candidates = [b for b in labels if timed[b] and 2 * timed[b] >= most and logs[b]] or labels
    strongest = max(candidates, key=lambda b: (sum(logs[b]) / len(logs[b]) if logs[b] else -math.inf,
                                               -labels.index(b)))
    never = [b for b in labels if not timed[b]]
    best = max(order, key=lambda m: (counts[(m, strongest)]["win"], -order.index(m)))
    c = counts[(best, strongest)]
    at_time = sum(c[v] for v in ("win", "tie", "loss"))
    lines = [
        "**Headline result** (the main job, `bash scripts/run-main.sh`: commit {}, {}, on {}; {} scenes, "
        "{} pixels each, timed at {} pixels; made by `scripts/readme-headline.py` from `{}`). At equal time "
        "{} wins {} of the {} scenes timed equal against {}{}{}".format(
            commit, date, "; ".join(devices), n_scenes, _sq(res), _sq(tres), RESULTS, best, c["win"], at_time,
            strongest, ", the strongest Monte Carlo here (the methods' NMSE closest to its)"
            if len(candidates) > 1 else "",
            " ({} more pairs off-time)".format(c["off-time"]) if c["off-time"] else "")
        + ("; against {} every pair was off-time (no verdict)".format(" and ".join(never)) if never else "")
        + ".",
        "",
        "Wins / ties / losses of each method against each baseline at equal time (a tie where the 95 % "
        "intervals over seeds overlap; off-time pairs, whose times differ by more than the tolerance, counted "
        "apart), and the geometric mean over those scenes of NMSE method / NMSE baseline:",
        "",
        "| method | " + " | ".join(_cell_text(b) for b in labels) + " |",
        "|---|" + "---|" * len(labels),
    ]
    for m in order:
        row = []
        for b in labels:
            rs = ratios[(m, b)]
            gm = ", {:.3g}x".format(math.exp(sum(map(math.log, rs)) / len(rs))) if rs else ""
            row.append(cell(counts[(m, b)]) + gm)
        lines.append("| `{}` | {} |".format(_cell_text(m), " | ".join(row)))
    lines += ["", filter_sentence()]
    lines += ["", "The baselines' full specs: " + "; ".join("{}: `{}`".format(b, s) for s, b in known.items()) + "."]
    lines += ["", "![NMSE against kernel time, geometric mean over the main job's scenes: every baseline's curve "
              "over N, every method a point]({})".format(FIGURE)]
    return "\n".join(lines)


def filter_sentence(files=FILTER_RESULTS):
    """The headline's sentence on the filter verdicts (see the module's doc)."""
    parts, devices = [], set()
    for name, path in files:
        doc = filter_verdicts.load(os.path.join(ROOT, path))
        rows = filter_verdicts.tally(doc)
        ctx = doc.get("context", {})
        devices.add(ctx.get("device", "?"))
        scenes = {r["scene"] for r in doc["records"] if r.get("role") == "method"}
        missing = [m for m, _ in FILTER_METHODS if m not in rows]
        if missing:
            raise ValueError("{}: no equal-time pairs of {}".format(path, ", ".join(missing)))
        wtl = filter_verdicts.wtl
        said = ", ".join("{} {} and {}".format(text, wtl(rows[m]["nmse"]), wtl(rows[m]["flip"]))
                         for m, text in FILTER_METHODS)
        pairs = sum(r["pairs"] for r in rows.values())
        off = sum(r["off_time"] for r in rows.values())
        floor = sum(r["floor"] for r in rows.values())
        below = sum(r.get("below_one", 0) for r in rows.values())
        parts.append("against {} ({} scenes, commit {}) {}; {} of {} pairs off-time, {} of them at the floor "
                     "(MC at its least scale takes longer than the method); {} pairs with MC below one sample "
                     "per pixel".format(name, len(scenes), (ctx.get("commit") or "?")[:7], said, off, pairs, floor,
                                        below))
    return ("Against a denoised Monte Carlo (`experiments/mc-baselines/strong-gauss-subpixel.json` and "
            "`strong-atrous-subpixel.json`: MC rendered at a share of the image's side and upsampled where one "
            "sample per pixel and the filter take longer than the method; "
            "on {}; from `{}`), wins / ties / losses in NMSE and in FLIP among the pairs on time: {}.".format(
                "; ".join(sorted(devices)), "` and `".join(p for _, p in files), "; ".join(parts)))


def _cell_text(s):
    """A name inside a Markdown table cell: its '|' escaped, no line breaks."""
    return " ".join(str(s).split()).replace("|", "\\|")


def _sq(values):
    return " / ".join("{0}^2".format(v) for v in values) or "?"


def block(text):
    return "{}\n{}\n{}".format(BEGIN, text, END)


def current(readme):
    """The README's text between the markers (None without them)."""
    with open(readme) as f:
        s = f.read()
    i, j = s.find(BEGIN), s.find(END)
    if i < 0 or j < i:
        return None, s
    return s[i + len(BEGIN) + 1:j - 1], s


def write_atomic(path, data, mode="w"):
    d = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=d, prefix=".tmp-" + os.path.basename(path))
    try:
        with os.fdopen(fd, mode) as f:
            f.write(data)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def check(results, readme, say=print):
    want = headline(load_records(results), load_context(results), results)
    have, _ = current(readme)
    if have is None:
        say("{}: no {} ... {} markers".format(readme, BEGIN, END))
        return 1
    if have != want:
        say("{}: the headline is not the one {} gives; run\n    /usr/bin/python3 scripts/readme-headline.py "
              "out/main/results.json\n(or with {}: it writes the README from that file)\n--- README\n{}\n--- "
              "from the results\n{}".format(readme, results, results, have, want))
        return 1
    if not os.path.exists(os.path.join(ROOT, FIGURE)):
        say("{}: missing (the headline's picture)".format(FIGURE))
        return 1
    say("readme-headline: {} matches {}".format(readme, results))
    return 0


def save_results(src, dst):
    """src (results.json[.xz]) as the xz file dst, atomically; nothing where they are one file."""
    import lzma
    if os.path.abspath(src) == os.path.abspath(dst):
        return
    opener = lzma.open if src.endswith(".xz") else open
    with opener(src, "rb") as f:
        data = f.read()
    write_atomic(dst, lzma.compress(data, preset=9), "wb")


def draw(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import error_time
    import style
    records = load_records(results)
    known = baselines(records, load_context(results))
    style.use()
    style.set_baselines(known.values())
    tmp = tempfile.mkdtemp()
    try:
        files = error_time.pooled_time(records, tmp, style.DPI, "nmse", "NMSE", known, per_luminaire=False,
                                       path=os.path.join(tmp, "figure.png"))
        png = next(f for f in files if f.endswith(".png"))
        shutil.copy(png, path + ".tmp")
        os.replace(path + ".tmp", path)
    finally:
        shutil.rmtree(tmp)


def generate(src, readme):
    dst = os.path.join(ROOT, RESULTS)
    save_results(src, dst)
    text = headline(load_records(dst), load_context(dst), RESULTS)
    have, s = current(readme)
    if have is None:
        raise SystemExit("{}: no {} ... {} markers to write between".format(readme, BEGIN, END))
    i, j = s.find(BEGIN), s.find(END) + len(END)
    write_atomic(readme, s[:i] + block(text) + s[j:])
    draw(dst, os.path.join(ROOT, FIGURE))
    print("readme-headline: {} and {} from {} (kept as {})".format(readme, FIGURE, src, RESULTS))


def self_test():
    """--check passes on the README's own results and fails where a number changes."""
    src = os.path.join(ROOT, RESULTS)
    have, _ = current(os.path.join(ROOT, "README.md"))
    text = headline(load_records(src), load_context(src), RESULTS)
    d = tempfile.mkdtemp()
    try:
        good, bad = os.path.join(d, "good.md"), os.path.join(d, "bad.md")
        with open(good, "w") as f:
            f.write("x\n" + block(text) + "\ny\n")
        i = next(k for k, ch in enumerate(text) if ch.isdigit() and k > text.find("wins"))
        with open(bad, "w") as f:
            f.write("x\n" + block(text[:i] + str((int(text[i]) + 1) % 10) + text[i + 1:]) + "\ny\n")
        # and a verdict count of the filter verdicts' sentence (robust's wins in NMSE)
        bad2 = os.path.join(d, "bad2.md")
        at = text.find(" robust ", text.find("Against a denoised"))
        i = next(k for k, ch in enumerate(text) if ch.isdigit() and k > at)
        with open(bad2, "w") as f:
            f.write("x\n" + block(text[:i] + str((int(text[i]) + 1) % 10) + text[i + 1:]) + "\ny\n")
        quiet = lambda *a: None  # noqa: E731
        ok = check(src, good, quiet) == 0 and check(src, bad, quiet) == 1 and check(src, bad2, quiet) == 1
    finally:
        shutil.rmtree(d)
    ok = several_baselines(load_records(src), load_context(src)) and ok
    print("readme-headline self-test: {}".format("passes" if ok else "FAILS"))
    return 0 if ok and have is not None else 1


def several_baselines(records, context):
    """The records' partners again as a second, labelled baseline whose pairs
    are all off-time: the headline has a column per baseline, counts the
    off-time pairs apart and names the second as one without a verdict."""
    import copy
    twin = []
    for r in records:
        if is_partner(r):
            c = copy.deepcopy(r)
            c["baseline"] = {"label": "twin", "spec": "mc:domain=twin"}
            c["equal_time"] = dict(c.get("equal_time") or {}, ok=False)
            c.pop("verdict", None)
            twin.append(c)
    text = headline(records + twin, context, "(two baselines)")
    head = next(line for line in text.split("\n") if line.startswith("| method |"))
    n = sum(1 for r in twin)
    found = [line for line in text.split("\n") if line.startswith("| `")]
    offs = sum(int(part.split("(")[-1].split(" off-time")[0]) for line in found for part in line.split("|")[-2:-1]
               if "off-time" in part)
    ok = head.endswith("| twin |") and "twin every pair was off-time" in text and offs == n
    if not ok:
        print("readme-headline self-test: two baselines: header {!r}, {} off-time of {}".format(head, offs, n))
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results", nargs="?", help="results.json[.xz] of the main job (default with --check: {})".format(
        RESULTS))
    ap.add_argument("--check", action="store_true", help="compare the README's headline with RESULTS")
    ap.add_argument("--self-test", action="store_true", help="show that --check fails on a changed headline")
    ap.add_argument("--readme", default=os.path.join(ROOT, "README.md"))
    a = ap.parse_args()
    try:
        if a.self_test:
            return self_test()
        if a.check:
            return check(a.results or os.path.join(ROOT, RESULTS), a.readme)
        if not a.results:
            ap.error("give the main job's results.json (e.g. out/main/results.json)")
        generate(a.results, a.readme)
    except (OSError, ValueError) as e:
        print("readme-headline: {}".format(e), file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
