#!/usr/bin/env python3
"""docs/studies/sh-engine.md: the tables of the sh-engine experiment from its results.json.

    .venv/bin/python experiments/sh-engine/summary.py DIR/results.json [--markdown]

Per luminaire and height: the geometric mean over the rotations of each method's NMSE and
the mean FLIP; per method and height the equal-time verdicts against the strong MC (win:
the method's NMSE below MC's 95 % interval over the seeds, loss: above, tie: inside), the
same in FLIP, per baseline, the pairs at equal time and those off it apart; each method's median time at the timing resolution."""
import argparse
import json
import math
import os
import statistics
import sys
from collections import defaultdict


def short(lum):
    return os.path.basename(lum).split("_")[0][:12]


def gmean(v):
    v = [x for x in v if x is not None and x > 0]
    return math.exp(sum(math.log(x) for x in v) / len(v)) if v else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results")
    a = ap.parse_args()
    with open(a.results) as f:
        doc = json.load(f)
    recs = doc["records"]
    methods = [r["spec"] for r in recs if r["role"] == "method"]
    methods = list(dict.fromkeys(methods))
    nm = defaultdict(list)  # (lum, h, spec) -> nmse per rotation
    fl = defaultdict(list)
    tm = defaultdict(list)
    for r in recs:
        if r["role"] != "method":
            continue
        key = (short(r["luminaire"]), r["height"], r["spec"])
        nm[key].append(r["nmse"])
        fl[key].append(r.get("flip"))
        tm[r["spec"]].append(r["time_ms"]["median"])
    lums = list(dict.fromkeys(k[0] for k in nm))
    hs = sorted({k[1] for k in nm})
    print("NMSE (geometric mean over R pi/2, 3pi/4, pi) / mean FLIP\n")
    print("| luminaire | h | " + " | ".join(methods) + " |")
    print("|---|---|" + "---|" * len(methods))
    for lum in lums:
        for h in hs:
            cells = []
            for m in methods:
                g = gmean(nm[(lum, h, m)])
                f = [x for x in fl[(lum, h, m)] if x is not None]
                cells.append(f"{g:.2g} / {statistics.mean(f):.3f}" if f else f"{g:.2g}")
            print(f"| {lum} | {h} | " + " | ".join(cells) + " |")
    # equal time, per baseline: NMSE and FLIP verdicts, pairs at equal time and off-time apart
    own = {}
    for r in recs:
        if r["role"] == "method":
            own[(r["scene"], r["spec"])] = r
    ver = defaultdict(lambda: [0, 0, 0])  # (label, h, baseline, metric, on-time) -> win tie loss
    for r in recs:
        if r["role"] != "equal_time":
            continue
        et = r["equal_time"]
        m = own.get((r["scene"], et["label"]))
        if m is None:
            continue
        base = r.get("baseline", {}).get("label", "MC")
        for metric in ("nmse", "flip"):
            if m.get(metric) is None or r.get(metric) is None:
                continue
            lo, hi = r.get("ci95", {}).get(metric, [r[metric], r[metric]])
            v = ver[(et["label"], r["height"], base, metric, bool(et["ok"]))]
            v[0 if m[metric] < lo else 2 if m[metric] > hi else 1] += 1
    print("\nEqual time against each MC (wins / ties / losses: NMSE; FLIP), pairs at equal time | off-time\n")
    print("| method | h | baseline | at equal time | off-time |")
    print("|---|---|---|---|---|")
    keys = sorted({k[:3] for k in ver})
    for lab, h, base in keys:
        cells = []
        for ok in (True, False):
            n, f = ver.get((lab, h, base, "nmse", ok)), ver.get((lab, h, base, "flip", ok))
            cells.append(f"{'/'.join(map(str, n))}; {'/'.join(map(str, f))}" if n else "-")
        print(f"| {lab} | {h} | {base} | {cells[0]} | {cells[1]} |")
    print("\nTime (ms, median over the scenes) at the timing resolution\n")
    for m in methods:
        print(f"- {m}: {statistics.median(tm[m]):.3f} ms")
    ctx = doc.get("context", {})
    print(f"\ncontext: {ctx.get('device')} {ctx.get('commit')} {ctx.get('date')}", file=sys.stderr)


if __name__ == "__main__":
    main()
