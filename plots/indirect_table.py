#!/usr/bin/env python3
"""Markdown tables of an indirect-scene run (lumibench run on
experiments/indirect*.json): NMSE per luminaire and method, and each
equal-time pair (the method against VPLs at its time).

    plots/indirect_table.py RESULTS.json"""
import json
import sys


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        doc = json.load(f)
    recs = doc["records"]
    lums = sorted({r["luminaire"].split("/")[-1].split("_")[0] for r in recs})
    specs = []
    for r in recs:
        if r["role"] == "method" and r["spec"] not in specs:
            specs.append(r["spec"])
    nm = {(r["luminaire"].split("/")[-1].split("_")[0], r["spec"]): r for r in recs if r["role"] == "method"}
    print("| luminaire | " + " | ".join(specs) + " |")
    print("|---" * (len(specs) + 1) + "|")
    for lum in lums:
        cells = [f"{nm[(lum, s)]['nmse']:.3g}" if (lum, s) in nm else "" for s in specs]
        print(f"| {lum} | " + " | ".join(cells) + " |")
    print()
    print("| luminaire | method | NMSE | VPLs at its time (N) | their NMSE |")
    print("|---|---|---|---|---|")
    for r in recs:
        if r["role"] != "equal_time":
            continue
        lum = r["luminaire"].split("/")[-1].split("_")[0]
        label = r.get("equal_time_label") or r.get("stats", {}).get("equal_time_label") or r["equal_time_to"]
        m = nm.get((lum, label))
        n = r["spec"].split("n=")[-1]
        print(f"| {lum} | {label} | {m['nmse']:.3g} | {n} | {r['nmse']:.3g} |" if m else
              f"| {lum} | {label} | | {n} | {r['nmse']:.3g} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
