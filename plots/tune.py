#!/usr/bin/env python3
"""Convergence plot of `lumibench tune`: objective per evaluation and the best so far.

Usage: /usr/bin/python3 plots/tune.py DIR/tune.json OUT.png
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from atomic import save_figure  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: tune.py tune.json out.png")
    doc = json.load(open(sys.argv[1]))
    trace = doc["trace"]
    metric = doc.get("metric", "nmse")  # files written before "metric" existed minimised NMSE
    k = [t["evaluation"] for t in trace]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(k, [t["objective"] for t in trace], ".", color="0.6", label="objective")
    ax.plot(k, [t["best"] for t in trace], "-", color="C0", label="best so far")
    # The equal-time objective is a mean log ratio (may be negative): linear axis.
    key = "objective" if doc["objective"] == "equal_time" else metric
    ax.axhline(doc["default"]["train_" + key], color="C1", ls="--", label="default (train)")
    if doc["objective"] == "equal_time":
        ax.set_ylabel(f"mean log({metric} / MCI's at equal time), training scenes")
    else:
        ax.set_yscale("log")
        ax.set_ylabel(f"{doc['objective']} {metric} over the training scenes")
    ax.set_xlabel("evaluation")
    ax.set_title(f"{doc['name']}: {doc['tuned']['algorithm']}, validation "
                 f"{doc['default']['validation_' + key]:.4g} -> {doc['tuned']['validation_' + key]:.4g}",
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
