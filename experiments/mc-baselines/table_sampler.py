#!/usr/bin/env python3
"""The table sampler (mc domain=table, mis_table, mis_table_solid) against projected, mis and
solid angle (docs/mc-baselines.md): NMSE at equal N (Owen-scrambled Sobol per
pixel) over seeds on 32^2 error images, the render time of the same spec at
--time-res, and the equal-time figure NMSE x time (the NMSE a sampler would
reach in projected's time if its NMSE fell as 1 / N), against projected.
Also --cost: each sampler's cost per sample against area sampling,
(t(64) - t(8)) / 56 (batwing, h 1, R 3pi/4, as `lumibench bench`).
Renders with build/lumibench (argument lists, no shell). Writes JSON to OUT
and a markdown table to stdout.

usage: table_sampler.py OUT.json [--n 16] [--seeds 2] [--res 32] [--time-res 128] [--cost]
       [--luminaires ARCOS3,MIREL,...]
"""
import argparse
import math
import os
import sys
import tempfile

from lbrun import ZUMTOBEL as ZUM, nmse, render as render_doc, write_json
SCENES = [(0.1, "pi/2"), (1.1, "pi")]
SAMPLERS = [
    ("projected", "mc:domain=projected,sequence=sobol"),
    ("mis (area + projected)", "mc:domain=mis,sequence=sobol"),
    ("solid", "mc:domain=solid,sequence=sobol"),
    ("table", "mc:domain=table,sequence=sobol"),
    ("mis_table (table + projected)", "mc:domain=mis_table,sequence=sobol"),
    ("mis_table_solid (table + solid)", "mc:domain=mis_table_solid,sequence=sobol"),
]


def render(lum, h, rot, spec, res, out, reps=1):
    """Renders spec; returns the median time (ms)."""
    return render_doc(lum, h, rot, spec, res, out, reps)["time_ms"]["median"]


def luminaires(names):
    out = []
    for n in names.split(","):
        hits = [f for f in sorted(os.listdir(ZUM)) if f.upper().startswith(n.upper() + "_")] if os.path.isdir(ZUM) else []
        out.append((n, os.path.join(ZUM, hits[0]) if hits else n))
    return out


def cost(tmp):
    out = os.path.join(tmp, "c.exr")
    t = lambda spec, n: render("batwing", 1, "3pi/4", f"{spec},n={n}", 128, out, reps=5)
    rows = {}
    for name, spec in [("area", "mc:domain=area")] + SAMPLERS:
        rows[name] = (t(spec, 64) - t(spec, 8)) / 56
    for name, c in rows.items():
        print(f"| {name} | {c:.4g} ms | {c / rows['area']:.1f}x |")
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--n", type=int, default=16)
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--res", type=int, default=32)
    ap.add_argument("--time-res", type=int, default=128)
    ap.add_argument("--cost", action="store_true")
    ap.add_argument("--luminaires", default="ARCOS3,INTRO,MIREL,PERLUCE,pencil,spot")
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="mctable")
    if a.cost:
        write_json(a.out, {"cost_ms_per_sample": cost(tmp)})
        return
    res = {}
    for name, path in luminaires(a.luminaires):
        for h, rot in SCENES:
            ref = os.path.join(tmp, "ref.exr")
            render(path, h, rot, "reference:tol=1e-4", a.res, ref)
            row = {}
            for sname, spec in SAMPLERS:
                vals = []
                for seed in range(1, a.seeds + 1):
                    out = os.path.join(tmp, "t.exr")
                    render(path, h, rot, f"{spec},n={a.n},seed={seed}", a.res, out)
                    vals.append(nmse(ref, out))
                ms = render(path, h, rot, f"{spec},n={a.n}", a.time_res, os.path.join(tmp, "tt.exr"), reps=3)
                row[sname] = {"nmse": sum(vals) / len(vals), "ms": ms}
            res[f"{name} h {h} R {rot}"] = row
            print(f"{name} h {h} R {rot} done", file=sys.stderr, flush=True)
            write_json(a.out, {"partial": True, "scenes": res})
    write_json(a.out, {"n": a.n, "seeds": a.seeds, "res": a.res, "time_res": a.time_res, "scenes": res})
    names = [s for s, _ in SAMPLERS]
    print(f"NMSE at N = {a.n} (equal-time figure: NMSE x time / projected's)")
    print("| scene | " + " | ".join(names) + " |")
    print("|---|" + "---|" * len(names))
    for sc, row in res.items():
        p = row["projected"]
        cells = [f"{row[s]['nmse']:.3g} ({row[s]['nmse'] * row[s]['ms'] / (p['nmse'] * p['ms']):.2g})" for s in names]
        print(f"| {sc} | " + " | ".join(cells) + " |")
    print("| time (ms, median over scenes) | " + " | ".join(
        f"{sorted(r[s]['ms'] for r in res.values())[len(res) // 2]:.3g}" for s in names) + " |")
    for s in names:
        g = math.exp(sum(math.log(max(r[s]["nmse"] * r[s]["ms"], 1e-300) / max(r["projected"]["nmse"] * r["projected"]["ms"], 1e-300)) for r in res.values()) / len(res))
        print(f"{s}: geometric mean of the equal-time figure against projected {g:.3g}")


if __name__ == "__main__":
    main()
