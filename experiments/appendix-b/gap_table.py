#!/usr/bin/env python3
"""Tables of docs/studies/appendix-b-gap.md from the results of experiments/appendix-b/*.json.

Reads one results.json[.xz] per run, or a .tar.xz of the runs' DIR/results.json
(experiments/results/appendix-b-gap-pocl-xeon.tar.xz: `lumibench merge` keeps one record
per cell, and extent and tol are not part of a cell); records are told apart by
inputs.extent, res and inputs.reference. Prints, per luminaire and height, the SCT (`cubature`) NMSE of the five rotations pooled into one stitched image
(plots/stitched_table.py: mean(MSE) / (mean(mean_ref) mean(mean_test))), the mean of the
five per-rotation NMSEs, and UEB / LEB over the rotations (max / min of test - reference,
lux), against S (extent), N (res) and the reference's tol. Standard library only.

Usage: python3 experiments/appendix-b/gap_table.py FILE.json[.xz]|RUNS.tar.xz... [--method cubature] [--pivot]
"""
import argparse, collections, json, lzma, os, re, sys, tarfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots"))
from stitched_table import stitched  # noqa: E402  (the pooling of docs/studies/thesis-sct-vs-mci.md)

THESIS = {("ARCOS", 0.1): (565.1048, 160.25, -8.4375), ("ARCOS", 1.1): (27.9669, 27.125, -11.8125),
          ("PERLUCE", 0.1): (0.2382, 18.7969, -4.25), ("PERLUCE", 1.1): (0.0007229, 0.64453, -0.25391)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("files", nargs="+")
    ap.add_argument("--method", default="cubature")
    ap.add_argument("--pivot", action="store_true", help="one table of stitched NMSE, rows S, columns N (reference tol 1e-4)")
    a = ap.parse_args()
    groups = collections.defaultdict(dict)   # (luminaire, h, S, N, tol) -> {rotation: record}
    docs = []
    for f in a.files:
        if f.endswith((".tar.xz", ".tar")):
            with tarfile.open(f) as t:
                docs += [json.load(t.extractfile(m)) for m in t.getmembers() if m.name.endswith("results.json")]
        else:
            with (lzma.open if f.endswith(".xz") else open)(f, "rt") as fh:
                docs.append(json.load(fh))
    for r in (r for d in docs for r in d["records"]):
        if r.get("role") != "method" or r["spec"] != a.method:
            continue
        tol = float(r["inputs"]["reference"].split("tol=")[-1])
        key = (re.sub(r"\d+$", "", r["luminaire"].split("_")[0]), r["height"], r["inputs"]["extent"], r["res"], tol)
        groups[key][r["rotation"]] = r   # the same cell in two runs (mc20000 repeats S 5, N 64): one
    groups = {k: list(v.values()) for k, v in groups.items()}
    if a.pivot:
        return pivot(groups)
    print(f"method {a.method}: stitched NMSE | mean of per-rotation NMSE | UEB | LEB | stitched mean_ref (lux)")
    for lh in sorted({k[:2] for k in groups}):
        t = THESIS.get(lh)
        print(f"\n{lh[0]} h {lh[1]:g}" + (f"  (thesis: NMSE {t[0]:g}, UEB {t[1]:g}, LEB {t[2]:g})" if t else ""))
        print("| S (m) | N | tol | stitched NMSE | mean per-rotation NMSE | UEB | LEB | mean_ref |")
        print("|---|---|---|---|---|---|---|---|")
        for k in sorted(k for k in groups if k[:2] == lh):
            g = groups[k]
            if len(g) != 5:
                print(f"| {k[2]:g} | {k[3]} | {k[4]:g} | ({len(g)} of 5 rotations) |")
                continue
            print(f"| {k[2]:g} | {k[3]} | {k[4]:g} | {stitched(g):.4g} | {sum(r['nmse'] for r in g) / 5:.3g} | "
                  f"{max(r['ueb'] for r in g):.4g} | {min(r['leb'] for r in g):.4g} | "
                  f"{sum(r['mean_ref'] for r in g) / 5:.4g} |")


def pivot(groups):
    """Rows S, columns N: reference tol 1e-4; a cell only run with tol 1e-3 (N 512) is marked *."""
    cell = {}
    for k, g in groups.items():
        if len(g) == 5 and (k[4] == 1e-4 or (k[4] == 1e-3 and k[:4] + (1e-4,) not in groups)):
            cell[k[:4]] = f"{stitched(g):.3g}" + ("" if k[4] == 1e-4 else "*")
    ss = sorted({k[2] for k in cell})
    ns = sorted({k[3] for k in cell})
    print("| luminaire, h | thesis | S (m) | " + " | ".join(f"N {n}" for n in ns) + " |")
    print("|---|---|---|" + "---|" * len(ns))
    for lh in sorted({k[:2] for k in cell}):
        for i, S in enumerate(ss):
            cells = [cell.get(lh + (S, n), "-") for n in ns]
            head = f"{lh[0]} h {lh[1]:g} | {THESIS[lh][0]:.4g}" if i == 0 and lh in THESIS else " | "
            print(f"| {head} | {S:g} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
