#!/usr/bin/env python3
"""NMSE against N per MC sampler and sequence on the published luminaires
(docs/mc-baselines.md). Renders with build/lumibench (argument lists, no
shell), compares against the reference, fits the log-log slope of the
geometric-mean NMSE over the scenes. Writes JSON to the path given as the
first argument and a markdown table to stdout.

usage: nmse_vs_n.py OUT.json [--res 32] [--seeds 2] [--ns 1,4,16,64,256]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(ROOT, "build", "lumibench")
LUMDIR = os.path.join(ROOT, "..", "shared", "luminaires", "zumtobel")
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


def render(lum, h, rot, spec, res, out):
    cmd = [BIN, "render", "--luminaire", lum, "--method", spec, "--height", str(h), "--rotation", rot,
           "--res", str(res), "--reps", "1", "--out", out, "--json"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def nmse(ref, test):
    r = subprocess.run([BIN, "compare", ref, test, "--json"], check=True, capture_output=True, text=True)
    return json.loads(r.stdout)["nmse"]


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
    a = ap.parse_args()
    ns = [int(x) for x in a.ns.split(",")]
    lums = sorted(f for f in os.listdir(LUMDIR) if f.lower().endswith(".ldt"))
    tmp = tempfile.mkdtemp(prefix="mcnmse")
    table = {name: {n: [] for n in ns} for name, _ in SAMPLERS}
    for lum in lums:
        path = os.path.join(LUMDIR, lum)
        for h, rot in SCENES:
            ref = os.path.join(tmp, "ref.exr")
            render(path, h, rot, "reference:tol=1e-4", a.res, ref)
            for name, spec in SAMPLERS:
                for n in ns:
                    vals = []
                    for seed in range(1, a.seeds + 1):
                        full = f"{spec}{',' if ':' in spec else ':'}n={n},seed={seed}"
                        out = os.path.join(tmp, "t.exr")
                        render(path, h, rot, full, a.res, out)
                        vals.append(nmse(ref, out))
                    table[name][n].append(sum(vals) / len(vals))
            print(f"{lum} h {h} R {rot} done", file=sys.stderr, flush=True)
            json.dump({"partial": True, "table": table}, open(a.out, "w"))
    rows = []
    for name, spec in SAMPLERS:
        gm = {n: math.exp(sum(math.log(max(v, 1e-300)) for v in table[name][n]) / len(table[name][n])) for n in ns}
        s = slope([math.log(n) for n in ns], [math.log(gm[n]) for n in ns])
        rows.append({"sampler": name, "spec": spec, "gmean_nmse": gm, "slope": s, "per_scene": table[name]})
    json.dump({"res": a.res, "seeds": a.seeds, "ns": ns, "scenes": SCENES, "luminaires": lums, "rows": rows},
              open(a.out, "w"), indent=1)
    print("| sampler | " + " | ".join(f"N={n}" for n in ns) + " | slope |")
    print("|---|" + "---|" * (len(ns) + 1))
    for r in rows:
        print(f"| {r['sampler']} | " + " | ".join(f"{r['gmean_nmse'][n]:.3g}" for n in ns) + f" | {r['slope']:.2f} |")


if __name__ == "__main__":
    main()
