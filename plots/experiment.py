#!/usr/bin/python3
"""Figures of an experiment run: reads DIR/results.json (or DIR/results.csv),
writes DIR/plots/*.png.

    /usr/bin/python3 plots/experiment.py DIR|DIR/results.json|DIR/results.csv [--max-grids K]

- nmse_time_<luminaire>_<precision>.png: NMSE against median kernel time,
  log-log, one panel per height (rows) and rotation (columns): the MCI curve
  (MC at N = 1..1024, `role` mci_curve) as a line, every method as a point,
  equal-time MCI partners as stars.
- nmse_h<height>_<precision>.png: mean NMSE over the rotations per luminaire,
  one line per method (thesis Figs. 6.7-6.10: one figure per height).
- grad_nmse_time_*, grad_nmse_h*, flip_time_*, flip_h*: the same for
  grad_nmse and FLIP (docs/design.md section 5), when some record carries them
  (flip is null where flip-evaluator was not available).
- grid_<scene>.png: reference | method | error for each method of a scene, from
  the PNG triples the runner saves with "save_images" (plots/image_grid.py);
  at most --max-grids scenes.

Only the JSON is read, so figures can be redone without re-running. Exits 3
when matplotlib is missing (lumibench then still writes report.md).
"""
import argparse
import collections
import math
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt
except ImportError:
    sys.stderr.write("experiment.py: matplotlib is missing (Debian: apt-get install python3-matplotlib; "
                     "run with /usr/bin/python3)\n")
    sys.exit(3)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import image_grid  # noqa: E402
from atomic import save_figure  # noqa: E402
from results_io import load_records  # noqa: E402


def finite(v):
    return isinstance(v, (int, float)) and math.isfinite(v)


def role(r):
    if "equal_time_to" in r:
        return "equal_time"
    return r.get("role", "method")


def label(r):
    if "equal_time_to" in r:
        return "MCI=" + r.get("equal_time_label", r["equal_time_to"])
    return r.get("spec", r["method"])


def stem(lum):
    return os.path.splitext(os.path.basename(lum))[0]


def safe(s):
    return "".join(c if c.isalnum() or c in ".-" else "_" for c in str(s))


def rot_label(rad):
    return "R={:.0f}°".format(math.degrees(rad))


def on_curve(r, cell):
    """An MCI-curve record, or a method record that is the same MC at some N
    (the runner keeps one cell when a method equals a curve point)."""
    if role(r) == "mci_curve":
        return True
    if role(r) != "method" or r["method"] != "mc":
        return False
    strip = lambda p: {k: v for k, v in p.items() if k != "n"}  # noqa: E731
    return any(role(c) == "mci_curve" and strip(c["params"]) == strip(r["params"]) for c in cell)


METRICS = (("nmse", "NMSE"), ("grad_nmse", "grad_nmse"), ("flip", "FLIP"))


def value(r, key):
    """The metric of a record, None where it is null or missing (older files)."""
    v = r.get(key)
    return v if finite(v) and v > 0 else None


def metric_time(records, out, dpi, key, name):
    """One figure per luminaire and precision; a panel per (height, rotation)."""
    by = collections.defaultdict(list)
    for r in records:
        by[(r["luminaire"], r["precision"])].append(r)
    files = []
    for (lum, prec), rs in sorted(by.items()):
        heights = sorted({r["height"] for r in rs})
        rots = sorted({r["rotation"] for r in rs})
        fig, axes = plt.subplots(len(heights), len(rots), figsize=(2.8 * len(rots), 2.4 * len(heights)),
                                 squeeze=False, sharex=True, sharey=True)
        methods = sorted({label(r) for r in rs if role(r) == "method"})
        ns = sorted({r["params"]["n"] for r in rs if on_curve(r, rs)})
        curve_ns = "{}..{}".format(ns[0], ns[-1]) if ns else ""  # one legend entry for every panel
        colours = {m: "C{}".format(i % 10) for i, m in enumerate(methods)}
        for i, h in enumerate(heights):
            for j, rot in enumerate(rots):
                ax = axes[i][j]
                cell = [r for r in rs if r["height"] == h and r["rotation"] == rot]
                curve = sorted((r["params"]["n"], r["time_ms"]["median"], value(r, key))
                               for r in cell if on_curve(r, cell) and value(r, key))
                if curve:
                    ax.plot([c[1] for c in curve], [c[2] for c in curve], "-", color="0.5", lw=1,
                            marker=".", ms=3, label="MCI curve (N = {})".format(curve_ns))
                for r in cell:
                    if not (value(r, key) and finite(r["time_ms"]["median"])):
                        continue
                    if role(r) == "method":
                        ax.plot(r["time_ms"]["median"], value(r, key), "o", color=colours[label(r)], ms=5,
                                label=label(r))
                    elif role(r) == "equal_time":
                        m = r.get("equal_time_label", "")
                        ax.plot(r["time_ms"]["median"], value(r, key), "*", ms=9, mec="k", mew=0.5,
                                color=colours.get(m, "k"), label="MCI=" + m + " (N={})".format(r.get("n")))
                ax.set_xscale("log")
                ax.set_yscale("log")
                # no minor ticks: on log axes over many decades they were most of the drawing time
                ax.minorticks_off()
                ax.grid(True, which="major", lw=0.3, alpha=0.5)
                if i == 0:
                    ax.set_title(rot_label(rot), fontsize=9)
                if j == 0:
                    ax.set_ylabel("h={} m\n{}".format(h, name), fontsize=9)
                if i == len(heights) - 1:
                    ax.set_xlabel("time (ms)", fontsize=9)
        handles, labels = {}, []
        for ax in axes.flat:
            for hd, lb in zip(*ax.get_legend_handles_labels()):
                entry = lb.split(" (N=")[0]
                if entry not in handles:
                    handles[entry] = hd
                    labels.append(entry)
        ncol = max(1, min(len(labels), 2 * len(rots)))
        rows = (len(labels) + ncol - 1) // ncol
        fig.legend([handles[k] for k in labels], labels, loc="lower center", ncol=ncol, fontsize=7)
        fig.suptitle("{} ({}): {} against run time".format(stem(lum), prec, name))
        # Fixed margins in inches instead of tight_layout, which took 70 % of
        # the plotting time (it measures every tick label of every panel):
        # left the two-line y label and tick labels, bottom the x label and
        # the legend's rows, top the title and the column titles.
        W, H = fig.get_size_inches()
        fig.set_size_inches(W, H + 0.2 * rows)
        H += 0.2 * rows
        fig.subplots_adjust(left=0.85 / W, right=1 - 0.12 / W, top=1 - 0.6 / H, bottom=(0.55 + 0.2 * rows) / H,
                            wspace=0.06, hspace=0.1)
        path = os.path.join(out, "{}_time_{}_{}.png".format(key, safe(stem(lum)), prec))
        save_figure(fig, path, dpi=dpi)
        plt.close(fig)
        files.append(path)
    return files


def metric_per_height(records, out, dpi, key, name):
    """Mean of a metric over the rotations per luminaire, one figure per height and precision."""
    acc = collections.defaultdict(list)
    for r in records:
        if role(r) == "mci_curve" or not finite(r.get(key)):
            continue
        acc[(r["height"], r["precision"], label(r), stem(r["luminaire"]))].append(r[key])
    files = []
    for h, prec in sorted({(k[0], k[1]) for k in acc}):
        lums = sorted({k[3] for k in acc if k[0] == h and k[1] == prec})
        labels = []
        for k in acc:
            if k[0] == h and k[1] == prec and k[2] not in labels:
                labels.append(k[2])
        labels.sort(key=lambda s: (s.startswith("MCI="), s))
        fig, ax = plt.subplots(figsize=(max(5, 1.0 * len(lums) + 2), 3.6))
        for i, lb in enumerate(labels):
            xs, ys = [], []
            for x, lum in enumerate(lums):
                v = acc.get((h, prec, lb, lum))
                if v and sum(v) > 0:
                    xs.append(x)
                    ys.append(sum(v) / len(v))
            ax.plot(xs, ys, "--" if lb.startswith("MCI=") else "-", marker="*" if lb.startswith("MCI=") else "o",
                    color="C{}".format(i % 10), label=lb)
        ax.set_xticks(range(len(lums)))
        ax.set_xticklabels(lums, rotation=30, ha="right", fontsize=8)
        ax.set_yscale("log")
        ax.set_ylabel("{} (mean over rotations)".format(name))
        ax.set_title("h = {} m ({})".format(h, prec))
        ax.grid(True, which="both", lw=0.3, alpha=0.5)
        ax.legend(fontsize=7)
        fig.tight_layout()
        path = os.path.join(out, "{}_h{}_{}.png".format(key, h, prec))
        save_figure(fig, path, dpi=dpi)
        plt.close(fig)
        files.append(path)
    return files


def grids(records, dir_, out, max_grids):
    """reference | method | error per scene from DIR/images/<scene>/<cell>_{ref,test,err}.png."""
    by = collections.OrderedDict()
    for r in records:
        if role(r) != "mci_curve" and "scene" in r:
            by.setdefault(r["scene"], []).append(r)
    files = []
    for scene, rs in list(by.items())[:max_grids]:
        rows = []
        for r in rs:
            cell = safe(r.get("spec", r["method"])) if role(r) == "method" else \
                "mci_eq_" + safe(r.get("equal_time_label", ""))
            prefix = os.path.join(dir_, "images", scene, cell)
            if os.path.exists(prefix + "_err.png"):
                name = label(r) + (" N={}".format(r["n"]) if "n" in r else "")
                rows.append("{}={}".format(name, prefix))
        if rows:
            path = os.path.join(out, "grid_{}.png".format(safe(scene)))
            image_grid.main(rows + ["--out", path, "--title", scene, "--size", "2.0", "--dpi", "100"])
            files.append(path)
    return files


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="results directory (with results.json or results.csv), or one of those files; "
                    "the figures go to plots/ beside it")
    ap.add_argument("--max-grids", type=int, default=8, help="image grids for at most this many scenes")
    ap.add_argument("--dpi", type=int, default=110)
    args = ap.parse_args(argv)
    try:
        records = load_records(args.dir)
    except (OSError, ValueError) as e:
        sys.exit("experiment.py: {}".format(e))
    if not os.path.isdir(args.dir):
        args.dir = os.path.dirname(os.path.abspath(args.dir))
    out = os.path.join(args.dir, "plots")
    os.makedirs(out, exist_ok=True)
    files = []
    for key, name in METRICS:
        if any(value(r, key) for r in records):  # none: older records, or no flip-evaluator
            files += metric_time(records, out, args.dpi, key, name) + metric_per_height(records, out, args.dpi, key, name)
    files += grids(records, args.dir, out, args.max_grids)
    print("experiment.py: {} figures in {}".format(len(files), out))


if __name__ == "__main__":
    main()
