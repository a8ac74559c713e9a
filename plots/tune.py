#!/usr/bin/env python3
"""Convergence plot of `lumibench tune`: objective per evaluation and the best so far.

With cross-validation two more panels: per fold the held-out luminaire's score of
the defaults and of the fold's tuned spec, and each parameter's tuned value per fold
in its search range (0 .. 1 of the range, log scale where the search is; a parameter
whose dots cover its range is over-fitted).

Usage: /usr/bin/python3 plots/tune.py DIR/tune.json OUT.png
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import style  # noqa: E402


def unit(v, d):
    """A parameter's value in its search range, 0 .. 1, in the search's scale."""
    lo, hi = d["lo"], d["hi"]
    if hi <= lo:
        return 0.0
    if d["scale"] == "log" and lo > 0:
        return min(1.0, max(0.0, math.log(max(v, lo) / lo) / math.log(hi / lo)))
    return min(1.0, max(0.0, (v - lo) / (hi - lo)))


def short(name):
    """A luminaire's file name without extension, cut to 12 characters."""
    return os.path.splitext(name)[0][:12]


def folds_panel(ax, cv, log_ratio):
    """Per fold the held-out score of the fold's tuned spec over the defaults' (below 1: better);
    the equal-time score (a mean log ratio) as tuned - default (below 0: better)."""
    folds = cv["folds"]
    if log_ratio:
        ratio = [f["tuned"] / f["default"] if f["default"] else float("nan") for f in folds]
    else:
        ratio = [f["tuned"] - f["default"] for f in folds]
    better = [f["tuned"] < f["default"] for f in folds]
    x = list(range(len(folds)))
    ax.axhline(1.0 if log_ratio else 0.0, color=style.OKABE_ITO["grey"], lw=0.8)
    ax.plot([i for i in x if better[i]], [ratio[i] for i in x if better[i]], "s", color=style.OKABE_ITO["blue"],
            label="tuned better")
    ax.plot([i for i in x if not better[i]], [ratio[i] for i in x if not better[i]], "o", mfc="none",
            color=style.OKABE_ITO["vermillion"], label="tuned not better")
    if log_ratio:
        ax.set_yscale("log")
    ax.set_xticks(x)
    ax.set_xticklabels([short(f["held_out"]) for f in folds], rotation=90)
    ax.set_ylabel("held out: tuned / default" if log_ratio else "held out: tuned - default")
    ax.set_title(f"leave one luminaire out ({cv['score']}): tuned better in {cv['folds_improved']} of {len(folds)}")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))


def spread_panel(ax, doc):
    folds = doc["cross_validation"]["folds"]
    dims = doc["search"]
    for i, d in enumerate(dims):
        us = [unit(f["params"][d["name"]], d) for f in folds]
        ax.plot([i] * len(us), us, "_", ms=10, color=style.OKABE_ITO["blue"], label="folds" if i == 0 else None)
        ax.plot([i], [unit(float(d["default"]), d)], "o", mfc="none", color=style.OKABE_ITO["vermillion"],
                label="default" if i == 0 else None)
        ax.plot([i], [unit(doc["tuned"]["params"][d["name"]], d)], "x", color=style.OKABE_ITO["black"],
                label="all luminaires" if i == 0 else None)
    ax.set_xticks(range(len(dims)))
    ax.set_xticklabels([d["name"] for d in dims], rotation=30)
    ax.set_ylim(-0.05, 1.05)
    ax.set_ylabel("tuned value in its range")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: tune.py tune.json out.png")
    doc = json.load(open(sys.argv[1]))
    trace = doc["trace"]
    metric = doc.get("metric", "nmse")  # files written before "metric" existed minimised NMSE
    k = [t["evaluation"] for t in trace]
    style.use()
    cv = doc.get("cross_validation")
    if cv:
        fig, (ax, axf, axs) = plt.subplots(3, 1, figsize=(style.TEXT_WIDTH * 0.8, 9.0), gridspec_kw={"hspace": 0.9})
        folds_panel(axf, cv, doc["objective"] != "equal_time")
        spread_panel(axs, doc)
    else:
        fig, ax = plt.subplots(figsize=(style.COLUMN_WIDTH, 2.6))
    ax.plot(k, [t["objective"] for t in trace], ".", color=style.OKABE_ITO["grey"], label="objective")
    ax.plot(k, [t["best"] for t in trace], "-", color=style.OKABE_ITO["blue"], label="best so far")
    # The equal-time objective is a mean log ratio (may be negative): linear axis.
    key = "objective" if doc["objective"] == "equal_time" else metric
    ax.axhline(doc["default"]["train_" + key], color=style.OKABE_ITO["vermillion"], ls="--", label="default (train)")
    if doc["objective"] == "equal_time":
        ax.set_ylabel(f"mean log({metric} / MCI's at equal time), training scenes")
    else:
        ax.set_yscale("log")
        ax.set_ylabel(f"{doc['objective']} {metric}, training")
    ax.set_xlabel("evaluation")
    # the title in two lines: the name, then the validation result (a long name is not cut)
    ax.set_title(f"{doc['name']}\n{doc['tuned']['algorithm']}: validation "
                 f"{doc['default']['validation_' + key]:.4g} -> {doc['tuned']['validation_' + key]:.4g}")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    style.save(fig, sys.argv[2])


if __name__ == "__main__":
    main()
