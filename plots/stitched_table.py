#!/usr/bin/env python3
"""Stitched-NMSE table of a `lumibench run` results.json (docs/studies/thesis-sct-vs-mci.md).

The thesis computes its figures and appendix B on the images of all rotations
stitched into one. From each record, MSE = NMSE * mean_ref * mean_test (thesis
Eq. 6.7: NMSE = MSE / (mean_ref mean_test)); over the rotations of one
(luminaire, height, method) with equal pixel counts the stitched image has the
mean MSE and the mean of the means, so
    NMSE_stitched = mean(MSE) / (mean(mean_ref) * mean(mean_test)).
Columns: every method of the experiment and, for each equal-time label, MCI at
its time with the mean N over the rotations in parentheses. Below the table:
in how many single scenes and stitched rows each method beats its equal-time
MCI, and how many equal-time pairs missed the tolerance. Standard library only.

Usage: python3 plots/stitched_table.py RESULTS [RESULTS ...] [--methods A,B,...]
(RESULTS: DIR/results.json[.xz], DIR/results.csv or DIR; a later file's records replace an
earlier one's of the same scene, role and spec.)

(The quantity is lumibench's own pooled NMSE, metrics::pooled in
host/metrics/metrics.h, which weights each rotation by its pixels; for equal
pixel counts, as here, that is the form above: results_io.pooled_nmse.)
"""
import argparse
import collections
import lzma
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from results_io import equal_time, load_records, pooled_nmse as stitched, verdict  # noqa: E402


def fmt(x):
    return f"{x:.3g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", nargs="+",
                    help="results files (.json, .json.xz); a later file's records replace an earlier one's of the "
                         "same scene, role and spec (e.g. one variant re-run on its own)")
    ap.add_argument("--methods", help="comma-separated method labels to show (default: all, in file order)")
    a = ap.parse_args()
    by_key = {}
    for path in a.results:
        try:
            for r in load_records(path):
                et = equal_time(r)
                key = (r.get("scene"), r.get("role"), et["label"] if et else r.get("spec"))
                by_key.pop(key, None)  # re-inserted last: the later file's order
                by_key[key] = r
        except (OSError, ValueError, lzma.LZMAError) as e:
            sys.exit(f"{path}: {e}")
    recs = list(by_key.values())
    methods, eq_labels = [], []
    groups = collections.defaultdict(list)   # (lum, h, column) -> records
    for r in recs:
        if r.get("role") == "method":
            col = r["spec"]
            if col not in methods:
                methods.append(col)
        elif r.get("role") == "equal_time":
            lab = equal_time(r)["label"]
            col = "mci@" + lab
            if lab not in eq_labels:
                eq_labels.append(lab)
        else:
            continue
        groups[(os.path.splitext(r["luminaire"])[0], r["height"], col)].append(r)
    if a.methods:
        methods = [m for m in a.methods.split(",")]
    cols = []
    for m in methods:
        cols.append(m)
        if m in eq_labels:
            cols.append("mci@" + m)
    keys = sorted({(k[0], k[1]) for k in groups})
    head = [c if not c.startswith("mci@") else "MCI at its time (mean N)" for c in cols]
    print("| luminaire | h | " + " | ".join(head) + " |")
    print("|---|---|" + "---|" * len(cols))
    for lum, h in keys:
        cells = []
        for c in cols:
            g = groups.get((lum, h, c), [])
            if not g:
                cells.append("-")
            elif c.startswith("mci@"):
                n = sum(equal_time(r)["n"] for r in g) / len(g)
                cells.append(f"{fmt(stitched(g))} ({n:.0f})")
            else:
                cells.append(fmt(stitched(g)))
        print(f"| {lum.split('_')[0]} | {h:g} | " + " | ".join(cells) + " |")
    print()
    by_scene = {(r["scene"], r["spec"]): r for r in recs if r.get("role") == "method"}
    for lab in eq_labels:
        eq = [r for r in recs if r.get("role") == "equal_time" and equal_time(r)["label"] == lab]
        verdicts = collections.Counter(verdict(by_scene[(r["scene"], lab)], r) for r in eq
                                       if (r["scene"], lab) in by_scene)
        ets = [equal_time(r) for r in eq]
        missed = sum(1 for et in ets if not et["ok"])
        # bracketed: N_eq's measured neighbour lies on the other side (no integer N is closer)
        closest = sum(1 for et in ets if et["ok"] or et["bracketed"])
        ns = sorted(et["n"] for et in ets)
        rows_won = sum(1 for lum, h in keys
                       if groups.get((lum, h, lab)) and groups.get((lum, h, "mci@" + lab))
                       and stitched(groups[(lum, h, lab)]) < stitched(groups[(lum, h, "mci@" + lab)]))
        print(f"- {lab}: beats its equal-time MCI in {verdicts['win']} of {len(eq)} scenes and {rows_won} of "
              f"{len(keys)} stitched rows; MCI N {ns[0]:g}..{ns[-1]:g} (median {ns[len(ns) // 2]:g}); pairs outside "
              f"the tolerance: {missed} ({100 * (len(eq) - missed) / len(eq):.0f} % within"
              + f", {100 * closest / len(eq):.0f} % within or bracketed)"
              + f"; verdicts {verdicts['win']} wins, {verdicts['tie']} ties, {verdicts['loss']} losses (95 % "
                "intervals over seeds where the records have them, a tie where they overlap)")


if __name__ == "__main__":
    main()
