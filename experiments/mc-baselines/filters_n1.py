#!/usr/bin/env python3
"""The filters at N = 1: NMSE, FLIP and the mean's bias of solid + sobol at
N = 1 unfiltered, + gauss16 and + atrous (which acts at N = 1 on SVGF's
spatial variance), against the reference, per scene and seed.

    python3 experiments/mc-baselines/filters_n1.py OUT.json [--res 128] [--seeds 4]
        [--luminaires ARCOS3,MIREL,SLOTLIGHT,PERLUCE] [--scenes 0.1:pi/2,1.1:3pi/4]

Images at --res (the filters' footprint scaled to it, methods/mc_denoise.h);
writes OUT.json atomically and prints the geometric means.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbrun import BIN, ZUMTOBEL, parse_scenes, render, write_json  # noqa: E402

MC = "mc:n=1,domain=solid,sequence=sobol"
FILTERS = {"none": "", "gauss16": ",denoise=gauss16", "atrous": ",denoise=atrous"}


def compare(ref, test):
    r = subprocess.run([BIN, "compare", ref, test, "--json"], check=True, capture_output=True, text=True)
    return json.loads(r.stdout)


def luminaire(prefix):
    for f in sorted(os.listdir(ZUMTOBEL)):
        if f.upper().startswith(prefix.upper()):
            return os.path.join(ZUMTOBEL, f)
    sys.exit(f"filters_n1.py: --luminaires: no file starting with {prefix!r} in {ZUMTOBEL}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--res", type=int, default=128)
    ap.add_argument("--seeds", type=int, default=4)
    ap.add_argument("--luminaires", default="ARCOS3,MIREL,SLOTLIGHT,PERLUCE")
    ap.add_argument("--scenes", default="0.1:pi/2,1.1:3pi/4")
    a = ap.parse_args()
    if not 8 <= a.res <= 4096 or not 1 <= a.seeds <= 64:
        sys.exit("filters_n1.py: --res 8 .. 4096, --seeds 1 .. 64")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.luminaires.split(","):
            lum = luminaire(name)
            for h, rot in parse_scenes(a.scenes, "filters_n1.py"):
                ref = os.path.join(tmp, "ref.exr")
                render(lum, h, rot, "reference:tol=1e-4", a.res, ref)
                for seed in range(1, a.seeds + 1):
                    for f, suffix in FILTERS.items():
                        img = os.path.join(tmp, "img.exr")
                        render(lum, h, rot, f"{MC},seed={seed}{suffix}", a.res, img)
                        c = compare(ref, img)
                        rows.append({"luminaire": os.path.basename(lum), "h": h, "rotation": rot, "seed": seed,
                                     "filter": f, "nmse": c["nmse"], "flip": c.get("flip"),
                                     "bias": c["mean_test"] / c["mean_ref"] - 1})
                print(f"{name} h {h} R {rot}: done", flush=True)
    summary = {}
    for f in FILTERS:
        rs = [r for r in rows if r["filter"] == f]
        summary[f] = {"nmse_geomean": math.exp(statistics.mean(math.log(r["nmse"]) for r in rs)),
                      "flip_mean": statistics.mean(r["flip"] for r in rs if r["flip"] is not None)
                      if any(r["flip"] is not None for r in rs) else None,
                      "bias_mean": statistics.mean(r["bias"] for r in rs),
                      "bias_range": [min(r["bias"] for r in rs), max(r["bias"] for r in rs)]}
        print(f, summary[f], flush=True)
    write_json(a.out, {"res": a.res, "seeds": a.seeds, "mc": MC, "rows": rows, "summary": summary})


if __name__ == "__main__":
    main()
