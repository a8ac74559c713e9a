#!/usr/bin/env python3
"""Convergence plot of `lumibench tune`: objective per evaluation and the best so far.

Usage: /usr/bin/python3 plots/tune.py DIR/tune.json OUT.png
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import style  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: tune.py tune.json out.png")
    doc = json.load(open(sys.argv[1]))
    trace = doc["trace"]
    metric = doc.get("metric", "nmse")  # files written before "metric" existed minimised NMSE
    k = [t["evaluation"] for t in trace]
    style.use()
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
        ax.set_ylabel(f"{doc['objective']} {metric} over the training scenes")
    ax.set_xlabel("evaluation")
    # the title in two lines: the name, then the validation result (a long name is not cut)
    ax.set_title(f"{doc['name']}\n{doc['tuned']['algorithm']}: validation "
                 f"{doc['default']['validation_' + key]:.4g} -> {doc['tuned']['validation_' + key]:.4g}")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    style.save(fig, sys.argv[2])


if __name__ == "__main__":
    main()
