#!/usr/bin/env python3
"""Tables of docs/studies/robust.md from a results.json (or results.csv) of `lumibench run`.

    plots/robust_table.py RESULTS [RESULTS ...] [--base point] [--out FILE.md]

RESULTS: a results directory, results.json[.xz] or results.csv. With more
than one, the records of a later file replace those of the earlier ones for
every luminaire the later file holds (e.g. one luminaire rerun with finer
error images).

For every method of the file: in how many scenes its NMSE is below the base
method's (default point), the geometric mean of NMSE / NMSE(base) per regime
(far field h >= 1.1; near the light's plane R = pi/2 at h = 0.1; the rest),
and, where the file has equal-time partners, the share of scenes where the
method beats MCI at its own measured time. Rows per luminaire follow.
"""
import argparse
import collections
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from atomic import emit_text  # noqa: E402
from results_io import load_records, matched, verdict  # noqa: E402


def spec_of(r):
    if matched(r):
        return None
    p = r.get("params") or {}
    return r["method"] + ":" + ",".join(f"{k}={p[k]}" for k in sorted(p))


def short(spec, defaults):
    name, _, rest = spec.partition(":")
    kept = [kv for kv in rest.split(",") if kv and kv not in defaults.get(name, set())]
    return name + (":" + ",".join(kept) if kept else "")


def regime(r):
    if r["height"] <= 0.11 and abs(r["rotation"] - math.pi / 2) < 1e-6:
        return "plane (h 0.1, R pi/2)"
    if r["height"] >= 1.05:
        return "far (h >= 1.1)"
    return "near (h 0.1, R > pi/2)"


def wtl(c):
    """wins / ties / losses of a Counter of verdicts (undefined ones apart)."""
    return f"{c['win']} / {c['tie']} / {c['loss']}" + (f" ({c['n/a']} undefined)" if c["n/a"] else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", nargs="+")
    ap.add_argument("--base", default="point")
    ap.add_argument("--out")
    a = ap.parse_args()
    try:
        recs = []
        for path in a.results:
            later = load_records(path)
            lums = {r["luminaire"] for r in later}
            recs = [r for r in recs if r["luminaire"] not in lums] + later
    except (OSError, ValueError) as e:
        sys.exit(f"robust_table: {e}")
    scene = lambda r: (r["luminaire"], r["height"], r["rotation"])
    nmse = collections.defaultdict(dict)  # scene -> spec -> nmse
    rec = collections.defaultdict(dict)   # scene -> spec -> record
    eq = collections.defaultdict(dict)    # scene -> target method -> MCI's record
    # parameters every spec of a method shares are its defaults here: left out of names
    by_method = collections.defaultdict(list)
    for r in recs:
        s = spec_of(r)
        if s is None:
            eq[scene(r)][matched(r)[0]] = r
        else:
            nmse[scene(r)][s] = r["nmse"]
            rec[scene(r)][s] = r
            by_method[r["method"]].append(set(s.partition(":")[2].split(",")))
    defaults = {m: set.intersection(*v) for m, v in by_method.items()}
    specs = sorted({s for d in nmse.values() for s in d})
    base = next((s for s in specs if s.split(":")[0] == a.base), None)
    if base is None:
        sys.exit(f"robust_table: no records of the base method '{a.base}' in {' '.join(a.results)}")
    regimes = sorted({regime({"height": k[1], "rotation": k[2]}) for k in nmse})
    out = ["| method | beats " + a.base + " | " + " | ".join(f"NMSE / {a.base}, {g}" for g in regimes) +
           " | against MCI at equal time (wins / ties / losses) |", "|---" * (3 + len(regimes)) + "|"]
    for s in specs:
        wins = n = 0
        logs = collections.defaultdict(list)
        eqv = collections.Counter()
        for k, d in nmse.items():
            if d.get(s) is None or d.get(base) is None:  # undefined (a black reference)
                continue
            n += 1
            wins += d[s] < d[base]
            if d[base] > 0 and d[s] > 0:
                logs[regime({"height": k[1], "rotation": k[2]})].append(math.log(d[s] / d[base]))
            # the partner of s: same method name, s the scene's only spec of that method
            same = [t for t in d if t.split(":")[0] == s.split(":")[0]]
            m = eq.get(k, {}).get(s.split(":")[0]) if same == [s] else None
            if m is not None:
                eqv[verdict(rec[k][s], m)] += 1
        cols = [f"{math.exp(sum(v) / len(v)):.3g}" if (v := logs.get(g)) else "-" for g in regimes]
        out.append(f"| `{short(s, defaults)}` | {wins} / {n} | " + " | ".join(cols) +
                   (f" | {wtl(eqv)} |" if eqv else " | - |"))
    out.append("")
    out.append("NMSE / " + a.base + ": geometric mean over the scenes of the regime (below 1: better than " +
               a.base + "); scenes whose NMSE is undefined (a black reference or method image) left out. "
               "Against MCI: a win where the method's NMSE lies below MCI's 95 % interval over its seeds, a loss "
               "where above, a tie where the interval reaches it (a single draw: its value).")
    # Per luminaire: scenes won against the base and against MCI at equal time.
    paired = [s for s in specs if any(s.split(":")[0] in e for e in eq.values())]
    if paired:
        out += ["", "| luminaire | " + " | ".join(f"`{short(s, defaults)}` beats {a.base}; against MCI W / T / L"
                                             for s in paired)
                + " |", "|---" * (1 + len(paired)) + "|"]
        for lum in sorted({k[0] for k in nmse}):
            cells = []
            for s in paired:
                w = n = 0
                ev = collections.Counter()
                for k, d in nmse.items():
                    if k[0] != lum or d.get(s) is None or d.get(base) is None:
                        continue
                    n += 1
                    w += d[s] < d[base]
                    m = eq.get(k, {}).get(s.split(":")[0])
                    if m is not None:
                        ev[verdict(rec[k][s], m)] += 1
                cells.append(f"{w} / {n}; {wtl(ev)}")
            out.append(f"| {os.path.basename(lum)} | " + " | ".join(cells) + " |")  # a path outside luminaire_dir too
    emit_text("\n".join(out) + "\n", a.out)


if __name__ == "__main__":
    main()
