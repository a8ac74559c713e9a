#!/usr/bin/python3
"""Figures of an experiment run: reads DIR/results.json (or DIR/results.csv),
writes DIR/plots/*.png (300 dpi) and a PDF beside each, in the suite's style
(plots/style.py, docs/figures.md: fixed colours and markers per method).

    /usr/bin/python3 plots/experiment.py DIR|DIR/results.json|DIR/results.csv [--max-grids K] [--jobs J]

- nmse_time_<luminaire>_<precision>.png: NMSE against median kernel time,
  log-log, one panel per height (rows) and rotation (columns): every Monte
  Carlo baseline's curve (MC at N = 1..1024, `role` mci_curve, one per
  baseline) as a line with N beside its points and its 95 % band over seeds,
  every method as a point with its intervals, equal-time partners hollow in
  their method's colour; one legend below the panels, the device and the
  timing resolution in the caption under it (plots/error_time.py).
- nmse_all_time_<precision>.png, nmse_by_luminaire_time_<precision>.png:
  the same pooled over scenes (geometric mean of the metric, its bounds and
  the times), one panel over every scene, and one panel per luminaire.
- nmse_h<height>_<precision>.png: NMSE per luminaire (categories on x), the
  rotations pooled into one stitched image as the report's tables do, each
  method a marker beside its hollow equal-time partner (thesis Figs.
  6.7-6.10: one figure per height).
- grad_nmse_time_*, grad_nmse_h*, flip_time_*, flip_h*: the same for
  grad_nmse and FLIP (docs/design.md section 5), when some record carries them
  (flip is null where flip-evaluator was not available).
- grids/grid_<scene>.png: reference | method | error for each method of a
  scene, from the PNG triples the runner saves with "save_images"
  (plots/image_grid.py), the error pictures on the scene's one bound with its
  colour bar (`lumibench report` draws them so), with the equal-time partners
  of one baseline (--grid-baseline; default the first the records name: a row
  per partner of every baseline made a grid of 20-40 cells and the report's
  longest step); every scene (or the first --max-grids), drawn by as many
  processes as there are CPUs.

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
import error_time  # noqa: E402
import image_grid  # noqa: E402
import style  # noqa: E402
from results_io import baselines, equal_time, load_context, load_records, pooled  # noqa: E402


def finite(v):
    return isinstance(v, (int, float)) and math.isfinite(v)


def role(r):
    if "equal_time_to" in r:
        return "equal_time"
    return r.get("role", "method")


def baseline_label(r):
    """The label of a partner's baseline ("MCI" for records of before baselines had names)."""
    b = r.get("baseline")
    return (b.get("label") if isinstance(b, dict) else b) or "MCI"


def label(r):
    """A grid row's name: the method's spec, or <baseline>=<method> for a partner."""
    if "equal_time_to" in r:
        return "{}={}".format(baseline_label(r), equal_time(r)["label"])
    return r.get("spec", r["method"])


def stem(lum):
    return os.path.splitext(os.path.basename(lum))[0]


def lum_name(r):
    """The luminaire as its file names it (the record's luminaire_name), else the file's stem."""
    return r.get("luminaire_name") or stem(r["luminaire"])


def wrapped(name, width=22):
    """A long name on lines of at most `width` characters (a category label on x)."""
    import textwrap
    return "\n".join(textwrap.wrap(name, width)) or name


def safe(s):
    return "".join(c if c.isalnum() or c in ".-" else "_" for c in str(s))


METRICS = (("nmse", "NMSE"), ("grad_nmse", "grad_nmse"), ("flip", "FLIP"))


def value(r, key):
    """The metric of a record, None where it is null or missing (older files)."""
    v = r.get(key)
    return v if finite(v) and v > 0 else None


def metric_per_height(records, out, dpi, key, name, known=None):
    """A metric per luminaire at one height, the rotations pooled as one
    stitched image (results_io.pooled, the report's metrics::pooled, not the
    mean of the rotations' values): luminaires are categories on x, each
    method a marker beside its equal-time partner (hollow). One figure per
    height and precision."""
    acc = collections.defaultdict(list)
    for r in records:
        if role(r) == "mci_curve" or not finite(r.get(key)):
            continue
        acc[(r["height"], r["precision"], error_time.series(r, known or {}), wrapped(lum_name(r)))].append(r)
    files = []
    for h, prec in sorted({(k[0], k[1]) for k in acc}):
        lums = sorted({k[3] for k in acc if k[0] == h and k[1] == prec})
        series = sorted({k[2] for k in acc if k[0] == h and k[1] == prec}, key=style.order)
        # the legend's width (style.legend_columns' estimate) in a margin at the right, all within the text width
        legend_w = 0.45 + 0.065 * max(len(line) for s in series for line in style.wrap(s).split("\n"))
        # (0.2 in spare: the first rotated luminaire name reaches left of the figure)
        W = min(style.TEXT_WIDTH - 0.2, max(style.COLUMN_WIDTH, 0.8 + legend_w + 0.45 * len(lums) * len(series) ** 0.5))
        fig, ax = plt.subplots(figsize=(W, 2.6))
        fig.subplots_adjust(left=0.65 / W, right=1 - (legend_w + 0.1) / W, top=1 - 0.25 / 2.6, bottom=0.75 / 2.6)
        slot = 0.8 / len(series)
        for j, s in enumerate(series):
            xs, ys = [], []
            for x, lum in enumerate(lums):
                v = pooled(acc[(h, prec, s, lum)], key) if (h, prec, s, lum) in acc else float("nan")
                if finite(v) and v > 0:
                    xs.append(x - 0.4 + slot * (j + 0.5))
                    ys.append(v)
            ax.plot(xs, ys, **style.plot_kw(s, label=error_time.legend_labels([s], known or {}, {})[0]))
        ax.set_xticks(range(len(lums)))
        ax.set_xticklabels(lums, rotation=30, ha="right")
        ax.set_xlim(-0.5, len(lums) - 0.5)
        for x in range(1, len(lums)):
            ax.axvline(x - 0.5, color="0.85", lw=0.6)
        ax.grid(False, axis="x")
        ax.set_yscale("log")
        ax.set_ylabel("{} (rotations pooled)".format(name))
        ax.set_title("h = {} m ({})".format(h, prec))
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
        path = os.path.join(out, "{}_h{}_{}.png".format(key, h, prec))
        files += style.save(fig, path, dpi=dpi)
        plt.close(fig)
    return files


def grid_rows(scene, rs, dir_, baseline=None):
    """image_grid.py's rows LABEL=PREFIX of a scene's method cells and the partner cells of
    one baseline (None: every baseline's) with pictures."""
    rows = []
    for r in rs:
        if role(r) == "method":
            cell = safe(r.get("spec", r["method"]))
        else:  # the runner's cellImageName: _vs_<baseline> for every baseline but MCI
            b = baseline_label(r)
            if baseline is not None and b != baseline:
                continue
            cell = "mci_eq_" + safe(equal_time(r)["label"] if "equal_time_to" in r else "") + \
                ("" if b == "MCI" else "_vs_" + safe(b))
        prefix = os.path.join(dir_, "images", scene, cell)
        if os.path.exists(prefix + "_err.png"):
            name = label(r) + (" N={}".format(r["n"]) if "n" in r else "")
            rows.append("{}={}".format(name, prefix))
    return rows


def one_grid(job):
    scene, rows, path, dpi = job
    style.use()
    with open(os.devnull, "w") as null:  # image_grid prints the path
        stdout, sys.stdout = sys.stdout, null
        try:
            image_grid.main(rows + ["--out", path, "--title=" + scene, "--size", "2.0", "--dpi", str(dpi)])
        finally:
            sys.stdout = stdout
    plt.close("all")
    return [path, os.path.splitext(path)[0] + ".pdf"]


def grids(records, dir_, out, max_grids, dpi, jobs=0, baseline=None):
    """reference | method | error per scene from DIR/images/<scene>/<cell>_{ref,test,err}.png,
    into OUT/grids/ (max_grids 0: every scene; jobs 0: one process per CPU), with the
    partners of the baseline labelled `baseline` (None: the first one the records name)."""
    by = collections.OrderedDict()
    for r in records:
        if role(r) != "mci_curve" and "scene" in r:
            by.setdefault(r["scene"], []).append(r)
    if baseline is None:
        baseline = next((baseline_label(r) for r in records if role(r) == "equal_time"), None)
    todo = []
    for scene, rs in list(by.items())[:max_grids or None]:
        rows = grid_rows(scene, rs, dir_, baseline)
        if rows:
            todo.append((scene, rows, os.path.join(out, "grids", "grid_{}.png".format(safe(scene))), dpi))
    if not todo:
        return []
    os.makedirs(os.path.join(out, "grids"), exist_ok=True)
    jobs = min(jobs or os.cpu_count() or 1, len(todo))
    if jobs <= 1:
        return [f for job in todo for f in one_grid(job)]
    import multiprocessing
    with multiprocessing.get_context("fork").Pool(jobs) as pool:
        return [f for files in pool.map(one_grid, todo) for f in files]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dir", help="results directory (with results.json or results.csv), or one of those files; "
                    "the figures go to plots/ beside it")
    ap.add_argument("--max-grids", type=int, default=0, help="image grids for at most this many scenes (0: all)")
    ap.add_argument("--jobs", type=int, default=0, help="processes drawing the grids (0: one per CPU)")
    ap.add_argument("--grid-baseline", default=None, metavar="LABEL",
                    help="the baseline whose equal-time partners the image grids show (default: the first)")
    ap.add_argument("--dpi", type=int, default=style.DPI, help="PNG resolution (default %(default)s)")
    args = ap.parse_args(argv)
    style.use()
    try:
        records = load_records(args.dir)
    except (OSError, ValueError) as e:
        sys.exit("experiment.py: {}".format(e))
    if not os.path.isdir(args.dir):
        args.dir = os.path.dirname(os.path.abspath(args.dir))
    out = os.path.join(args.dir, "plots")
    os.makedirs(out, exist_ok=True)
    known = baselines(records, load_context(args.dir))
    style.set_baselines(known.values())
    files = []
    for key, name in METRICS:
        if any(value(r, key) for r in records):  # none: older records, or no flip-evaluator
            files += error_time.metric_time(records, out, args.dpi, key, name, known)
            files += error_time.pooled_time(records, out, args.dpi, key, name, known, per_luminaire=False)
            files += error_time.pooled_time(records, out, args.dpi, key, name, known)
            files += metric_per_height(records, out, args.dpi, key, name, known)
    files += grids(records, args.dir, out, args.max_grids, args.dpi, args.jobs, args.grid_baseline)
    print("experiment.py: {} figures in {}".format(len(files), out))


if __name__ == "__main__":
    main()
