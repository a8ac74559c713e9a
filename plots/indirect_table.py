#!/usr/bin/env python3
"""Markdown tables of an indirect-scene run (lumibench run on
experiments/indirect*.json):

  - NMSE per luminaire and method (geometric mean over the luminaire's
    heights and rotations; with one scene per luminaire, its value),
  - NMSE per height and method (geometric mean over luminaires and rotations),
  - times at the run's timing resolution (median over the scenes of each
    cell's median; the RSM, clustering and evaluation stages of the stateful
    methods from their stage_ms),
  - equal time per method: pairs, the share timed within the run's tolerance,
    wins (the method's NMSE below that of the VPLs at its time), the median
    VPL count N and the geometric mean of NMSE(method) / NMSE(VPLs at its time),
  - with --pairs, every equal-time pair.

    plots/indirect_table.py RESULTS.json [--pairs]"""
import json
import lzma
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from results_io import equal_time  # noqa: E402


def short(lum):
    return lum.split("/")[-1].split("_")[0]


def gmean(xs):
    xs = [x for x in xs if x > 0]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else float("nan")


def load(path):
    opener = lzma.open if path.endswith(".xz") else open
    with opener(path, "rt") as f:
        return json.load(f)


def label_of(r):
    return equal_time(r)["label"]


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    doc = load(args[0])
    recs = doc["records"]
    tol = doc.get("context", {}).get("equal_time_tolerance")
    time_res = doc.get("context", {}).get("time_res")
    methods = [r for r in recs if r["role"] == "method"]
    specs = []
    for r in methods:
        if r["spec"] not in specs:
            specs.append(r["spec"])
    short_spec = {s: s for s in specs}
    # The experiment's label of each method (what equal_time names) when present.
    for r in methods:
        short_spec[r["spec"]] = r.get("label", r["spec"])
    lums = sorted({short(r["luminaire"]) for r in methods})
    heights = sorted({r["height"] for r in methods})
    scenes = {r["scene"] for r in methods}
    print(f"{len(scenes)} scenes, {len(methods)} method cells, "
          f"{sum(r['role'] == 'equal_time' for r in recs)} equal-time pairs\n")

    def table(keys, keyname, keyfn):
        print(f"| {keyname} | " + " | ".join(short_spec[s] for s in specs) + " |")
        print("|---" * (len(specs) + 1) + "|")
        for k in keys:
            cells = []
            for s in specs:
                xs = [r["nmse"] for r in methods if r["spec"] == s and keyfn(r) == k]
                cells.append(f"{gmean(xs):.3g}" if xs else "")
            print(f"| {k} | " + " | ".join(cells) + " |")
        print()

    print("NMSE (geometric mean over the scenes):\n")
    table(lums, "luminaire", lambda r: short(r["luminaire"]))
    if len(heights) > 1:
        table(heights, "height (m)", lambda r: r["height"])

    print(f"Times at {time_res}^2 (ms, median over the scenes):\n")
    print("| method | time | rsm | cluster | eval |")
    print("|---|---|---|---|---|")
    for s in specs:
        rs = [r for r in methods if r["spec"] == s]
        t = statistics.median(r["time_ms"]["median"] for r in rs)
        stages = []
        for st in ("rsm", "cluster", "eval"):
            xs = [r["stats"]["stage_ms"][st] for r in rs if st in r.get("stats", {}).get("stage_ms", {})]
            stages.append(f"{statistics.median(xs):.1f}" if xs else "")
        print(f"| {short_spec[s]} | {t:.1f} | " + " | ".join(stages) + " |")
    print()

    by_cell = {(r["scene"], r["spec"]): r for r in methods}
    pairs = [r for r in recs if r["role"] == "equal_time"]
    labels = []
    for p in pairs:
        if label_of(p) not in labels:
            labels.append(label_of(p))
    tol_text = f"+-{100 * tol:.0f} %" if tol is not None else "tolerance"
    print(f"Equal time (VPLs at the method's time; timed within {tol_text}):\n")
    print(f"| method | pairs | within {tol_text} | wins | median N | NMSE / NMSE(VPLs), geometric mean |")
    print("|---|---|---|---|---|---|")
    for lab in labels:
        ps = [p for p in pairs if label_of(p) == lab]
        ratios, wins = [], 0
        for p in ps:
            m = by_cell.get((p["scene"], label_of(p)))
            if m is None:
                continue
            ratios.append(m["nmse"] / p["nmse"])
            wins += m["nmse"] < p["nmse"]
        ok = sum(bool(equal_time(p)["ok"]) for p in ps)
        n = statistics.median(equal_time(p)["n"] or 0 for p in ps)
        print(f"| {lab} | {len(ps)} | {ok} ({100 * ok / len(ps):.0f} %) | {wins} of {len(ratios)} | {n:g} | "
              f"{gmean(ratios):.3g} |")
    print()

    if "--pairs" in argv:
        print("| scene | method | NMSE | VPLs at its time (N) | their NMSE | time ratio |")
        print("|---|---|---|---|---|---|")
        for p in pairs:
            m = by_cell.get((p["scene"], label_of(p)))
            nm = f"{m['nmse']:.3g}" if m else ""
            print(f"| {p['scene']} | {label_of(p)} | {nm} | {equal_time(p)['n']} | {p['nmse']:.3g} | "
                  f"{equal_time(p)['ratio'] if equal_time(p)['ratio'] is not None else float('nan'):.3f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
