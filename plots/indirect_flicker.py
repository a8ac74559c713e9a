#!/usr/bin/env python3
"""Flicker and mean NMSE against the cluster count K from `lumibench sequence`
outputs (docs/studies/indirect.md): one line per method family (vpl by N, kmeans and
acrsm by K), one panel per metric.

    plots/indirect_flicker.py OUT.png SEQ.json [SEQ.json ...]

Each SEQ.json holds "flicker", "flicker_seq" and "mean" per SPEC; K (or N) is
read from the SPEC's k= (n=) value. flicker_seq (frame differences normalised
by the sequence's mean reference level) is what is plotted; files written
before it existed get it from their per-frame records (flicker x mean_ref x
mean_test is the frame's mean squared difference). A markdown table of every
SPEC goes to stdout."""
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import style  # noqa: E402


def count(spec):
    m = re.search(r"[:,](k|n)=(\d+)", spec)
    return int(m.group(2)) if m else None


def flicker_seq(doc, spec):
    if "flicker_seq" in doc and spec in doc["flicker_seq"]:
        return doc["flicker_seq"][spec]
    frames = doc["frames"]
    diff = [f["methods"][spec]["flicker"] * f["methods"][spec]["mean_ref"] * f["methods"][spec]["mean_test"]
            for f in frames[1:]]
    level = sum(f["methods"][spec]["mean_ref"] for f in frames) / len(frames)
    return sum(diff) / len(diff) / (level * level)


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    series = {}
    for path in argv[2:]:
        with open(path) as f:
            doc = json.load(f)
        label = doc.get("luminaire", path).split("/")[-1]
        path_kind = doc["path"]["kind"]
        print(f"\n{label}, path {path_kind}, {doc['path']['frames']} frames\n")
        print("| SPEC | flicker (per sequence) | flicker (per frame) | mean NMSE | mean time (ms) |")
        print("|---|---|---|---|---|")
        for spec, flf in doc["flicker"].items():
            fl = flicker_seq(doc, spec)
            print(f"| {spec} | {fl:.4g} | {flf:.4g} | {doc['mean'][spec]['nmse']:.4g} | "
                  f"{doc['mean'][spec]['time_ms']:.1f} |")
            k = count(spec)
            if k is None or fl is None:
                continue
            fam = spec.split(":")[0]
            series.setdefault((f"{label} {path_kind}", fam), []).append((k, fl, doc["mean"][spec]["nmse"]))
    style.use()
    fig, axes = plt.subplots(1, 2, figsize=(style.TEXT_WIDTH, 2.6))
    # one line style per sequence (file), the colour and marker of the method family
    dashes = {}
    for (label, fam), pts in sorted(series.items()):
        pts.sort()
        ks = [p[0] for p in pts]
        ls = ["-", "--", ":", "-."][dashes.setdefault(label, len(dashes)) % 4]
        for ax, col in ((axes[0], 1), (axes[1], 2)):
            kw = style.plot_kw(fam, line=True, label=f"{fam} ({label})")
            kw["linestyle"] = ls
            ax.plot(ks, [p[col] for p in pts], **kw)
    for ax, title in zip(axes, ["flicker (per sequence)", "mean NMSE over the frames"]):
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("K clusters (vpl: N lights)")
        ax.set_title(title)
    labels = [lb for lb in axes[0].get_legend_handles_labels()[1]]
    fig.legend(*axes[0].get_legend_handles_labels(), loc="upper center", bbox_to_anchor=(0.5, 0.0),
               ncol=style.legend_columns(labels, style.TEXT_WIDTH))
    fig.tight_layout()
    style.save(fig, argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
