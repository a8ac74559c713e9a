#!/usr/bin/python3
"""Figure grid: reference | method | error, one row per comparison.

Each row is the PNG triple that `lumibench compare --png PREFIX` writes:
PREFIX_ref.png, PREFIX_test.png (tone mapped, L/(1+L) of L = k E) and
PREFIX_err.png (orange too bright, blue too dark, white no error, magenta
non-finite). When PREFIX.json exists (`lumibench compare ... --json --png PREFIX
> PREFIX.json`), its NMSE, UEB and LEB are printed under the error picture, as
in the thesis' tables (Prost 2019, Table 6.2), and its `bound`, `mean_ref` and
`colour_bar` give the error pictures a colour bar in lux and in % of the
reference mean: one bar beside the error column where every row has the same
bound, else one per row.

Give every row of one figure the same --k and the same --bound in `compare`,
so that the pictures are comparable (thesis 6.2); `lumibench run` and
`report` draw a scene's pictures at one bound (docs/figures.md).

    python3 plots/image_grid.py --out fig.png \\
        "cubature h=0.1=out/cub_h0.1" "MCI-40 h=0.1=out/mc40_h0.1"

A row is LABEL=PREFIX or just PREFIX; where both hold '=', the PREFIX is the
longest tail after an '=' whose pictures exist.
"""
import argparse
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.image as mpimg  # noqa: E402
import numpy as np  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.cm import ScalarMappable  # noqa: E402
from matplotlib.colors import LinearSegmentedColormap, Normalize  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import style  # noqa: E402

# The colours of host/metrics/tonemap.h (kOrange, kBlue, kNonFinite), for the legend.
ORANGE, BLUE, MAGENTA = (213 / 255, 94 / 255, 0.0), (0.0, 128 / 255, 1.0), (1.0, 0.0, 1.0)


def parse_row(spec):
    """'label=prefix' or 'prefix' -> (label, prefix).

    Labels ("mc:n=8") and prefixes (a luminaire named "a=b") may both hold
    '=': the prefix is the longest tail after an '=' whose pictures exist,
    else what follows the last '='."""
    if os.path.exists(spec + "_err.png"):
        return os.path.basename(spec), spec
    cuts = [i for i, c in enumerate(spec) if c == "="]
    for i in cuts:
        if os.path.exists(spec[i + 1:] + "_err.png"):
            return spec[:i], spec[i + 1:]
    if cuts:
        return spec[:cuts[-1]], spec[cuts[-1] + 1:]
    return os.path.basename(spec), spec


def fmt(v, spec):
    return "n/a" if v is None or (isinstance(v, float) and not math.isfinite(v)) else format(v, spec)


def scale(prefix):
    """(bound, mean_ref, colours) of PREFIX.json's error scale, or None (no file,
    no bound, or an exact picture: bound 0)."""
    path = prefix + ".json"
    if not os.path.exists(path):
        return None
    with open(path) as f:
        m = json.load(f)
    b, colours = m.get("bound"), m.get("colour_bar")
    if not isinstance(b, (int, float)) or not b > 0 or not colours:
        return None
    return float(b), float(m.get("mean_ref") or 0), list(colours)


def signed(v):
    """+4, -2.5, +8420: three significant digits, whole numbers from 1000 on (no exponent)."""
    return "0" if v == 0 else format(v, "+.0f" if abs(v) >= 1000 else "+.3g")


def colour_bar(fig, cax, sc):
    """A vertical bar from -bound to +bound in the pictures' colours, ticks
    in lux and in % of the reference mean."""
    bound, mean, colours = sc
    cmap = LinearSegmentedColormap.from_list("lumibench_error", colours, N=257)  # odd: 0 is a colour of its own
    cmap.set_under(colours[0])
    cmap.set_over(colours[-1])
    cax.set_gid("colour_bar")
    bar = fig.colorbar(ScalarMappable(Normalize(-bound, bound), cmap), cax=cax, extend="both")
    ticks = [-bound, -bound / 2, 0.0, bound / 2, bound]
    bar.set_ticks(ticks)
    bar.set_ticklabels(["{} lx".format(signed(t)) + ("\n{} %".format(signed(100 * t / mean)) if mean > 0 else "")
                        for t in ticks])
    bar.ax.tick_params(labelsize=style.MIN_FONT_PT)
    bar.set_label("test - reference", fontsize=style.MIN_FONT_PT)
    return bar


def caption(prefix):
    """NMSE / UEB / LEB (and grad_nmse / FLIP where the file has them) from PREFIX.json, or ''.
    Short lines (at most about 24 characters), so that the caption fits under a picture."""
    path = prefix + ".json"
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        m = json.load(f)
    lines = ["NMSE {}".format(fmt(m.get("nmse"), ".3g")),
             "UEB {} lx".format(fmt(m.get("ueb"), "+.3g")),
             "LEB {} lx".format(fmt(m.get("leb"), "+.3g"))]
    if "grad_nmse" in m or "flip" in m:
        lines.append("grad_nmse {}".format(fmt(m.get("grad_nmse"), ".3g")))
        lines.append("FLIP {}".format(fmt(m.get("flip"), ".3g")))
    if m.get("nonfinite"):
        lines.append("{} non-finite px".format(m["nonfinite"]))
    # two per line where they fit side by side
    return "\n".join("   ".join(lines[i:i + 2]) if len(" ".join(lines[i:i + 2])) <= 26 else
                     "\n".join(lines[i:i + 2]) for i in range(0, len(lines), 2))


def inside(fig, artist):
    """Whether `artist`'s drawn extent lies within the figure (after a draw)."""
    fig.canvas.draw()
    box = artist.get_window_extent(renderer=fig.canvas.get_renderer())
    W, H = fig.canvas.get_width_height()
    return box.x0 >= -0.5 and box.y0 >= -0.5 and box.x1 <= W + 0.5 and box.y1 <= H + 0.5


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rows", nargs="+", help="LABEL=PREFIX or PREFIX (PNGs of lumibench compare --png PREFIX)")
    ap.add_argument("--out", required=True, help="output figure (.png, .pdf, .svg)")
    ap.add_argument("--columns", default="Reference,Method,Error", help="three column titles, comma separated")
    ap.add_argument("--title", default="", help="figure title")
    ap.add_argument("--size", type=float, default=2.6, help="size of one picture in inches (default 2.6)")
    ap.add_argument("--dpi", type=int, default=style.DPI)
    ap.add_argument("--no-legend", action="store_true", help="leave out the legend of the error colours")
    args = ap.parse_args(argv)
    style.use()

    columns = args.columns.split(",")
    if len(columns) != 3:
        ap.error("--columns needs three comma-separated titles")
    rows = [parse_row(r) for r in args.rows]
    for _, prefix in rows:
        for suffix in ("_ref.png", "_test.png", "_err.png"):
            if not os.path.exists(prefix + suffix):
                sys.exit(f"image_grid: {prefix + suffix} not found (write it with lumibench compare --png {prefix})")

    n = len(rows)
    lines = max([caption(p).count("\n") + 1 for _, p in rows if caption(p)] + [0])
    height = n * (args.size + 0.35 + 0.14 * lines) + (0 if args.no_legend else 0.3)
    scales = [scale(p) for _, p in rows]
    shared = all(scales) and len({sc[0] for sc in scales}) == 1
    bars = any(scales)
    fig = plt.figure(figsize=(3 * args.size + (0.9 if bars else 0), height))
    grid = fig.add_gridspec(n, 4 if bars else 3, width_ratios=[1, 1, 1, 0.07] if bars else [1, 1, 1])
    axes = np.array([[fig.add_subplot(grid[i, j]) for j in range(3)] for i in range(n)])
    for i, (label, prefix) in enumerate(rows):
        for j, suffix in enumerate(("_ref.png", "_test.png", "_err.png")):
            ax = axes[i][j]
            ax.imshow(mpimg.imread(prefix + suffix), interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            if i == 0:
                ax.set_title(columns[j])
        axes[i][0].set_ylabel(label)
        axes[i][2].set_xlabel(caption(prefix), fontsize=style.MIN_FONT_PT)
        if scales[i] and not shared:
            colour_bar(fig, fig.add_subplot(grid[i, 3]), scales[i])
    if shared:
        colour_bar(fig, fig.add_subplot(grid[:, 3]), scales[0])
    if args.title:
        fig.suptitle(args.title)
    # Room at the bottom for the legend of the error colours (0.3 inch).
    legend_frac = 0 if args.no_legend else 0.3 / fig.get_figheight()
    fig.tight_layout(rect=(0, legend_frac, 1, 1))
    if not args.no_legend:
        legend = [Patch(color=ORANGE, label="too bright"),
                  Patch(facecolor="white", edgecolor="0.5", label="no error"),
                  Patch(color=BLUE, label="too dark"),
                  Patch(color=MAGENTA, label="non-finite")]
        fig.legend(handles=legend, loc="lower center", ncol=4, frameon=False)
    for ax in axes[:, 2]:
        if ax.xaxis.label.get_text() and not inside(fig, ax.xaxis.label):
            sys.stderr.write("image_grid: warning: a caption does not fit the figure (--size larger?)\n")
    style.save(fig, args.out, dpi=args.dpi)  # and a PDF (or PNG) beside it
    plt.close(fig)
    print(args.out)
    return fig


if __name__ == "__main__":
    main()
