#!/usr/bin/env python3
"""The specular extension's tables and figure (docs/specular.md) from a
`lumibench run` of experiments/specular*.json: error against time per alpha,
and where Cubature + LTC beats Monte Carlo at equal time.

    plots/specular.py RESULTS [--md OUT.md] [--fig OUT.png] [--metric nmse]

RESULTS: results.json(.xz) or results.csv. Per alpha, a scene's error is its
record's metric; tables give the geometric mean over the scenes (luminaires x
heights x rotations) and win counts of `ltc` (the paper's Cubature + LTC)
against MCI at its time (the runner's equal-time partner).
"""
import argparse
import collections
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from results_io import load_records, matched  # noqa: E402


def label(r):
    m = matched(r)
    if m:  # MCI at the time of the method: the method's name as below (results.json or .csv alike)
        return "MCI=" + label({"method": m[0], "params": m[1], "spec": m[0] + (":" if m[1] else "") +
                               ",".join("{}={}".format(k, v) for k, v in m[1].items())})
    p = r.get("params", {})
    if r["method"] == "ltc":
        parts = []
        if p.get("radiance", "cubature") != "cubature":
            parts.append("radiance=" + p["radiance"])
        if p.get("triangulation", "fan") != "fan":
            parts.append("triangulation=" + p["triangulation"])
        if p.get("g_omega", "estimate") != "estimate":
            parts.append("g_omega=" + p["g_omega"])
        if p.get("lookup", "lut") != "lut":
            parts.append("lookup=" + p["lookup"])
        return "ltc" + (":" + ",".join(parts) if parts else "")
    if r["method"] == "mc":
        s = p.get("sampling", "light")
        return "mc:n=%d" % p.get("n", 0) + ("" if s == "light" else ",sampling=" + s)
    return r.get("spec", r["method"])


def gmean(v):
    v = [x for x in v if x is not None and x > 0 and math.isfinite(x)]
    return math.exp(sum(math.log(x) for x in v) / len(v)) if v else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results")
    ap.add_argument("--md", help="write the tables here (else stdout)")
    ap.add_argument("--fig", help="error-time figure (PNG)")
    ap.add_argument("--metric", default="nmse")
    a = ap.parse_args()
    recs = [r for r in load_records(a.results) if r.get("scene_kind") == "specular"]
    if not recs:
        sys.exit("%s: no specular records" % a.results)
    m = a.metric
    by = collections.defaultdict(list)  # (alpha, label) -> records
    for r in recs:
        by[(r["alpha"], label(r))].append(r)
    alphas = sorted({k[0] for k in by})
    labels = sorted({k[1] for k in by}, key=lambda s: (not s.startswith("ltc"), s.startswith("MCI"), s))
    curve = [l for l in labels if l.startswith("mc:n=") and "sampling" not in l]
    curve.sort(key=lambda s: int(s.split("=")[1]))
    shown = [l for l in labels if l not in curve or l == "mc:n=8"]
    out = []
    out.append("### %s: geometric mean over the scenes, per alpha\n" % m.upper())
    out.append("| method | " + " | ".join("alpha %g" % x for x in alphas) + " | median time (ms) |")
    out.append("|---" * (len(alphas) + 2) + "|")
    for l in shown:
        cells = [gmean([r.get(m) for r in by.get((x, l), [])]) for x in alphas]
        ts = sorted(r["time_ms"]["median"] for x in alphas for r in by.get((x, l), []))
        t = ts[len(ts) // 2] if ts else float("nan")
        extra = ""
        if l.startswith("MCI"):
            ns = [r.get("n") for x in alphas for r in by.get((x, l), []) if r.get("n")]
            extra = " (median N = %d)" % sorted(ns)[len(ns) // 2] if ns else ""
        out.append("| %s%s | " % (l, extra) + " | ".join("%.3g" % c for c in cells) + " | %.3g |" % t)
    # wins of ltc against its equal-time MCI, per alpha and height
    out.append("\n### Cubature + LTC against MCI at equal time: scenes where its %s is lower\n" % m.upper())
    heights = sorted({r["height"] for r in recs})
    out.append("| height | " + " | ".join("alpha %g" % x for x in alphas) + " |")
    out.append("|---" * (len(alphas) + 1) + "|")
    for h in heights:
        row = []
        for x in alphas:
            lt = {r["scene"]: r.get(m) for r in by.get((x, "ltc"), []) if r["height"] == h}
            mc = {r["scene"]: r.get(m) for r in by.get((x, "MCI=ltc"), []) if r["height"] == h}
            keys = [k for k in lt if k in mc and lt[k] is not None and mc[k] is not None]
            wins = sum(lt[k] < mc[k] for k in keys)
            ratio = gmean([lt[k] / mc[k] for k in keys if mc[k] > 0])
            row.append("%d / %d (x%.2g)" % (wins, len(keys), ratio))
        out.append("| %g | " % h + " | ".join(row) + " |")
    out.append("\n(x: geometric mean of %s(ltc) / %s(MCI at its time); < 1 means Cubature + LTC is better.)" % (m, m))
    text = "\n".join(out) + "\n"
    if a.md:
        with open(a.md + ".tmp", "w") as f:
            f.write(text)
        os.replace(a.md + ".tmp", a.md)
    else:
        sys.stdout.write(text)
    if a.fig:
        figure(by, alphas, curve, shown, m, a.fig)


def figure(by, alphas, curve, shown, m, path):
    """Error against time per alpha (a panel each), in the suite's style:
    the MC curve with N beside its points, each method in its fixed colour
    and marker, MCI at equal time hollow. Written as PNG and PDF."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import style
    style.use()
    pw = min(2.2, (style.TEXT_WIDTH - 0.7) / len(alphas))
    fig, axes = plt.subplots(1, len(alphas), figsize=(0.7 + pw * len(alphas), 0.6 + 0.9 * pw), sharey=True,
                             squeeze=False)
    axes = axes[0]
    for ax, x in zip(axes, alphas):
        pts = [(int(l.split("=")[1]), gmean([r["time_ms"]["median"] for r in by[(x, l)]]),
                gmean([r.get(m) for r in by[(x, l)]])) for l in curve if (x, l) in by]
        if pts:
            ax.plot([p[1] for p in pts], [p[2] for p in pts], **style.plot_kw(style.CURVE))
            for i, (n, t, e) in enumerate(pts):
                if len(pts) <= 6 or i % 2 == 0 or i == len(pts) - 1:
                    ax.annotate(str(n), (t, e), xytext=(2, 2), textcoords="offset points", color="0.25")
        for l in shown:
            if l in curve or (x, l) not in by:
                continue
            t = gmean([r["time_ms"]["median"] for r in by[(x, l)]])
            e = gmean([r.get(m) for r in by[(x, l)]])
            ax.plot([t], [e], **style.plot_kw(l))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title("alpha %g" % x)
        ax.set_xlabel("time (ms)")
    axes[0].set_ylabel("%s (geometric mean over scenes)" % m.upper())
    handles = {}
    for ax in axes:
        for hd, lb in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(lb, hd)
    names = sorted(handles, key=style.order)
    if curve:
        names_l = [style.wrap(n if n != style.CURVE else "MCI curve (light sampling; N %s..%s at the points)" %
                              (curve[0].split("=")[1], curve[-1].split("=")[1])) for n in names]
    else:
        names_l = [style.wrap(n) for n in names]
    W = fig.get_figwidth()
    fig.legend([handles[n] for n in names], names_l, loc="upper center", bbox_to_anchor=(0.5, 0.0),
               ncol=style.legend_columns(names_l, W))
    fig.subplots_adjust(left=0.6 / W, right=1 - 0.05 / W, bottom=0.45 / fig.get_figheight(), wspace=0.08)
    style.save(fig, path)


if __name__ == "__main__":
    main()
