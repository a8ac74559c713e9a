#!/usr/bin/python3
"""The parameter-scan tables of docs/tuning.md from the committed runs of
experiments/tune-plane-scan.json and experiments/tune-area-scan.json
(experiments/tune/tune-{plane,area}-scan-results.csv.xz): per spec, on how many of the
20 luminaires its geometric mean NMSE over the luminaire's scenes beats robust's
(better, equal), the geometric mean over the 19 luminaires other than the pencil of
that ratio, the worst ratio, and the luminaires where it loses. Scenes with an undefined
NMSE (a black reference) are left out of a luminaire's mean.
usage: experiments/tune/scan_table.py [RESULTS.csv[.xz] ...]"""
import collections
import csv
import io
import lzma
import math
import os
import sys


def table(path):
    op = lzma.open if path.endswith(".xz") else open
    with op(path, "rt") as f:
        rows = list(csv.DictReader(io.StringIO(f.read())))
    nm = collections.defaultdict(lambda: collections.defaultdict(dict))
    for r in rows:
        if r["role"] != "method":
            continue
        try:
            v = float(r["nmse"])
        except ValueError:
            v = float("nan")
        nm[r["series"]][r["luminaire"].split("/")[-1]][r["scene"]] = v
    rob = nm["robust"]

    def geo(d):
        vs = [v for v in d.values() if math.isfinite(v) and v > 0]
        return math.exp(sum(map(math.log, vs)) / len(vs))

    out = []
    for s, d in nm.items():
        if s == "robust":
            continue
        g = {lum: geo(d[lum]) / geo(rob[lum]) for lum in rob}
        others = [math.log(g[lum]) for lum in g if "pencil" not in lum]
        out.append((sum(v < 1 for v in g.values()), sum(v == 1 for v in g.values()),
                    math.exp(sum(others) / len(others)), max(g.values()), s,
                    [lum.split(".")[0][:10] for lum in g if g[lum] > 1]))
    print(f"\n{os.path.basename(path)}\n")
    print("| spec | better than robust | equal | geomean ratio (19, no pencil) | worst ratio | loses on |")
    print("|---|---|---|---|---|---|")
    for w, e, gm, mx, s, lo in sorted(out, key=lambda x: (-x[0], x[2])):
        print(f"| `{s}` | {w} | {e} | {gm:.4f} | {mx:.3f} | {', '.join(lo)} |")


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for p in sys.argv[1:] or [os.path.join(here, f"tune-{k}-scan-results.csv.xz") for k in ("plane", "area")]:
        table(p)
