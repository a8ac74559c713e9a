#!/usr/bin/env python3
"""docs/studies/sh-engine.md: per-pixel blends of sh into robust, measured on saved images.

    PYTHONPATH=build/python .venv/bin/python experiments/sh-engine/blend.py OUT [--near 0.25,0.5,1,2]

OUT: a run of experiments/sh-engine/sh-blend.json (its images/ hold each scene's
reference.exr, robust.exr and sh_near_0.exr (sh without a blend) at 32 x 32, and the other
methods' images, printed in the experiment's order). Per pixel the predictor is the angle the
light's diagonal subtends from the pixel, size = sqrt(W^2 + L^2) / |x - c| (docs/design.md:
the light's centre c at (0, 0, h + L / 2), the image a square of side S centred on the
origin): the blend renders sh where size >= 2 near, robust where size <= near, linearly
between, E = (1 - t) E_sh + t E_robust with t = clamp((2 near - size) / near, 0, 1). Prints
per height the geometric mean of NMSE and the mean FLIP (lumibench.compare) of robust, sh
and each blend over the scenes, and per blend the scenes where it is worse than robust by
more than 5 % in NMSE; the kernels' median times from OUT/results.json."""
import argparse
import json
import math
import os
import statistics
import sys
from collections import defaultdict

import numpy as np

import lumibench


def size_map(h, n, extent=5.0, w=1.0, l=1.0):
    """The angle (radians) the light's diagonal subtends from each pixel centre."""
    t = -extent / 2 + (np.arange(n) + 0.5) * extent / n
    x = t[None, :]
    y = -t[:, None]
    d = np.sqrt(x * x + y * y + (h + l / 2) ** 2)
    return math.hypot(w, l) / d


def blend(sh, robust, size, near):
    t = np.clip((2 * near - size) / near, 0.0, 1.0)
    return ((1 - t) * sh + t * robust).astype(np.float32)


def gmean(v):
    return math.exp(sum(math.log(max(x, 1e-300)) for x in v) / len(v))


def scenes(out):
    root = os.path.join(out, "images")
    for d in sorted(os.listdir(root)):
        p = os.path.join(root, d)
        if all(os.path.exists(os.path.join(p, f + ".exr")) for f in ("reference", "robust", "sh_near_0")):
            h = float(d.split("_h")[1].split("_")[0])
            yield d, h, p


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--near", default="0.25,0.5,1,2", help="comma-separated near values (radians)")
    a = ap.parse_args()
    nears = [float(x) for x in a.near.split(",")]
    with open(os.path.join(a.out, "results.json")) as f:
        specs = dict.fromkeys(r["spec"] for r in json.load(f)["records"] if r["role"] == "method")
    # the runner's image names: the SPEC as written in the experiment, ':', ',' and '=' as '_'
    kernel = [sp.replace(":", "_").replace(",", "_").replace("=", "_") for sp in specs]
    kernel = [k for k in kernel if k != "robust"]
    labels = ["robust"] + kernel + [f"to robust near={x:g}" for x in nears]
    nm = defaultdict(list)  # (h, label) -> NMSE per scene
    fl = defaultdict(list)
    worse = defaultdict(list)
    for name, h, p in scenes(a.out):
        ref = lumibench.read_exr(os.path.join(p, "reference.exr"))
        rob = lumibench.read_exr(os.path.join(p, "robust.exr"))
        ks = [lumibench.read_exr(os.path.join(p, k + ".exr")) for k in kernel]
        sh = ks[kernel.index("sh_near_0")]
        size = size_map(h, ref.shape[0])
        imgs = [rob] + ks + [blend(sh, rob, size, x) for x in nears]
        for lab, img in zip(labels, imgs):
            m = lumibench.compare(ref, img)
            nm[(h, lab)].append(m["nmse"])
            fl[(h, lab)].append(m["flip"])
        for lab in labels[1:]:
            if nm[(h, lab)][-1] > 1.05 * nm[(h, "robust")][-1]:
                worse[lab].append(f"{name} {nm[(h, lab)][-1]:.3g} vs {nm[(h, 'robust')][-1]:.3g}")
    hs = sorted({h for h, _ in nm})
    print("NMSE (geometric mean over the scenes) / mean FLIP\n")
    print("| h | scenes | " + " | ".join(labels) + " |")
    print("|---|---|" + "---|" * len(labels))
    for h in hs:
        cells = [f"{gmean(nm[(h, lab)]):.2g} / {statistics.mean(fl[(h, lab)]):.3f}" for lab in labels]
        print(f"| {h} | {len(nm[(h, 'robust')])} | " + " | ".join(cells) + " |")
    print("\nScenes where a blend's NMSE exceeds robust's by more than 5 %\n")
    for lab in labels[1:]:
        print(f"- {lab}: {len(worse[lab])}" + "".join(f"\n  - {w}" for w in worse[lab]))
    times(a.out)
    return 0


def times(out):
    """Each method's median time over the scenes (ms at the timing resolution) and per height."""
    with open(os.path.join(out, "results.json")) as f:
        recs = [r for r in json.load(f)["records"] if r["role"] == "method"]
    by = defaultdict(list)
    for r in recs:
        by[(r["spec"], r["height"])].append(r["time_ms"]["median"])
    specs = list(dict.fromkeys(r["spec"] for r in recs))
    hs = sorted({r["height"] for r in recs})
    print("\nMedian time (ms per frame at the timing resolution) by height\n")
    print("| method | " + " | ".join(f"h {h}" for h in hs) + " |")
    print("|---|" + "---|" * len(hs))
    for sp in specs:
        print(f"| {sp} | " + " | ".join(f"{statistics.median(by[(sp, h)]):.3g}" for h in hs) + " |")


if __name__ == "__main__":
    sys.exit(main())
