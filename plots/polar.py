#!/usr/bin/env python3
"""Polar plot of a luminaire's C0-C180 and C90-C270 planes (absolute cd).

Input: the JSON of `lumibench luminaire dump FILE --json` (a file, or - for
stdin), or a luminaire file, which is dumped with build/lumibench.

    plots/polar.py luminaires/batwing.ldt -o batwing.png
    build/lumibench luminaire dump X.ies --json | plots/polar.py - -o x.png

Gamma 0 (the main emission axis) points down; C0 is drawn on the right and
C180 on the left, C90 right and C270 left (dashed). Values between the table's
gammas are the table's own bilinear interpolation along the plane.
"""
import argparse
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import style  # noqa: E402


def load(src, binary):
    if src == "-":
        return json.load(sys.stdin)
    if src.endswith(".json"):
        with open(src) as f:
            return json.load(f)
    out = subprocess.run([binary, "luminaire", "dump", src, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def plane(d, c_deg):
    """Intensity over the table's gammas in plane C (linear in C between planes)."""
    c = np.asarray(d["c"])
    g = np.asarray(d["gamma"])
    cd = np.asarray(d["cd"]).reshape(len(c), len(g))
    i = min(max(np.searchsorted(c, c_deg, side="right") - 1, 0), len(c) - 2)
    t = (c_deg - c[i]) / (c[i + 1] - c[i])
    return g, (1 - t) * cd[i] + t * cd[i + 1]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("src", help="luminaire file, dump JSON, or - for stdin")
    ap.add_argument("-o", "--out", default="polar.png", help="output picture (.png or .pdf: both are written; .svg as well)")
    ap.add_argument("--binary", default=os.path.join(here, "..", "build", "lumibench"))
    ap.add_argument("--title", default=None)
    a = ap.parse_args()
    d = load(a.src, a.binary)

    style.use()
    fig = plt.figure(figsize=(style.COLUMN_WIDTH, style.COLUMN_WIDTH))
    ax = fig.add_subplot(projection="polar")
    ax.set_theta_zero_location("S")  # gamma 0 down
    ax.set_theta_direction(1)        # counter-clockwise: right half first
    blue, vermillion = style.OKABE_ITO["blue"], style.OKABE_ITO["vermillion"]
    planes = (((0, 180), "-", blue, "C0-C180"), ((90, 270), "--", vermillion, "C90-C270"))
    for (c_right, c_left), ls, colour, label in planes:
        g, right = plane(d, c_right)
        _, left = plane(d, c_left)
        theta = np.concatenate([np.radians(g), -np.radians(g[::-1])])
        r = np.concatenate([right, left[::-1]])
        ax.plot(theta, r, ls, color=colour, label=label)
    ax.set_thetagrids(range(0, 360, 30), [f"{x if x <= 180 else 360 - x}" for x in range(0, 360, 30)])
    ax.set_title(a.title or os.path.basename(d.get("file") or "luminaire"))
    # the legend and the summary below the plot, outside the data
    ax.legend(loc="upper left", bbox_to_anchor=(-0.1, -0.12), ncol=2)
    fig.text(0.02, -0.13, f"cd, max {d['max_cd']:.0f}; flux {d['flux_lm']:.0f} lm")
    style.save(fig, a.out)


if __name__ == "__main__":
    main()
