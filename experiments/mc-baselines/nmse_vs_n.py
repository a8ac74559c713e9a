#!/usr/bin/env python3
"""NMSE against N per MC sampler and sequence on the published luminaires
(docs/mc-baselines.md). Renders with build/lumibench (argument lists, no
shell), compares against the reference, fits the log-log slope of the
geometric-mean NMSE over the scenes. Writes JSON to the path given as the
first argument and a markdown table to stdout.

usage: nmse_vs_n.py OUT.json [--res 32] [--seeds 2] [--ns 1,4,16,64,256]
                     [--set samplers|mis-split] [--scenes 0.1:3pi/4,1.1:pi/2]

--set mis-split: mis (area + projected by the balance heuristic) at several
shares of N for the projected technique, against area and projected alone.
"""
import argparse
import math
import os
import sys
import tempfile

from lbrun import ZUMTOBEL as LUMDIR, nmse, parse_scenes, render, write_json
SCENES = [(0.1, "3pi/4"), (1.1, "pi/2")]
SAMPLERS = [
    ("area, shared (MCI)", "mc"),
    ("area, random", "mc:domain=area,sequence=random"),
    ("solid, random", "mc:domain=solid,sequence=random"),
    ("solid, sobol", "mc:domain=solid,sequence=sobol"),
    ("paper MC (solid, Halton + shift)", "mc:paper=1"),
    ("projected, sobol", "mc:domain=projected,sequence=sobol"),
    ("projected, zsobol", "mc:domain=projected,sequence=zsobol"),
    ("mis, sobol", "mc:domain=mis,sequence=sobol"),
]
MIS_SPLIT = [
    ("area, sobol", "mc:domain=area,sequence=sobol"),
    ("solid, sobol", "mc:domain=solid,sequence=sobol"),
    ("projected, sobol", "mc:domain=projected,sequence=sobol"),
    ("mis 0.25 projected, sobol", "mc:domain=mis,sequence=sobol,mis_split=0.25"),
    ("mis 0.5 projected, sobol", "mc:domain=mis,sequence=sobol,mis_split=0.5"),
    ("mis 0.75 projected, sobol", "mc:domain=mis,sequence=sobol,mis_split=0.75"),
    ("mis 0.9 projected, sobol", "mc:domain=mis,sequence=sobol,mis_split=0.9"),
]


def slope(xs, ys):
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    sxx = sum((x - mx) ** 2 for x in xs)
    return sxy / sxx


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--res", type=int, default=32)
    ap.add_argument("--seeds", type=int, default=1)
    ap.add_argument("--ns", default="1,4,16,64,256")
    ap.add_argument("--set", choices=["samplers", "mis-split"], default="samplers")
    ap.add_argument("--scenes", default=",".join(f"{h}:{r}" for h, r in SCENES))
    a = ap.parse_args()
    ns = [int(x) for x in a.ns.split(",")]
    samplers = SAMPLERS if a.set == "samplers" else MIS_SPLIT
    scenes = parse_scenes(a.scenes, "nmse_vs_n.py")
    lums = sorted(f for f in os.listdir(LUMDIR) if f.lower().endswith(".ldt"))
    tmp = tempfile.mkdtemp(prefix="mcnmse")
    table = {name: {n: [] for n in ns} for name, _ in samplers}
    for lum in lums:
        path = os.path.join(LUMDIR, lum)
        for h, rot in scenes:
            ref = os.path.join(tmp, "ref.exr")
            render(path, h, rot, "reference:tol=1e-4", a.res, ref)
            for name, spec in samplers:
                for n in ns:
                    vals = []
                    for seed in range(1, a.seeds + 1):
                        full = f"{spec}{',' if ':' in spec else ':'}n={n},seed={seed}"
                        out = os.path.join(tmp, "t.exr")
                        render(path, h, rot, full, a.res, out)
                        vals.append(nmse(ref, out))
                    table[name][n].append(sum(vals) / len(vals))
            print(f"{lum} h {h} R {rot} done", file=sys.stderr, flush=True)
            write_json(a.out, {"partial": True, "table": table})
    rows = []
    for name, spec in samplers:
        gm = {n: math.exp(sum(math.log(max(v, 1e-300)) for v in table[name][n]) / len(table[name][n])) for n in ns}
        s = slope([math.log(n) for n in ns], [math.log(gm[n]) for n in ns])
        rows.append({"sampler": name, "spec": spec, "gmean_nmse": gm, "slope": s, "per_scene": table[name]})
    write_json(a.out, {"res": a.res, "seeds": a.seeds, "ns": ns, "scenes": scenes, "luminaires": lums, "rows": rows})
    print("| sampler | " + " | ".join(f"N={n}" for n in ns) + " | slope |")
    print("|---|" + "---|" * (len(ns) + 1))
    for r in rows:
        print(f"| {r['sampler']} | " + " | ".join(f"{r['gmean_nmse'][n]:.3g}" for n in ns) + f" | {r['slope']:.2f} |")


if __name__ == "__main__":
    main()
