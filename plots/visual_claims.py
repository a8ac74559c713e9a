#!/usr/bin/env python3
"""Tables of docs/studies/visual-claims.md from the results of experiments/visual-claims.json.

    plots/visual_claims.py RESULTS [--out FILE.md]

RESULTS: a results directory, results.json[.xz] or results.csv of `lumibench run`.
Methods are named as in the seeds: SCT (the paper's cubature, fan + CP),
voronoi, Delaunay+ (Delaunay over CP, NP, MRP and the barycentre), MCI-24,
MCI-40 and MCI-eq (MC at the measured time of SCT). Three metrics: NMSE,
grad_nmse (neighbouring-pixel differences, sees bumps and ripples) and FLIP
(mean HDR-FLIP). Prints, in Markdown:

1. per luminaire and regime (h 0.1: near the light; h >= 1.1: far), each
   method's geometric-mean NMSE and grad_nmse and arithmetic-mean FLIP;
2. per luminaire and regime, SCT's mean error over MCI-24's and MCI-40's, and
   in how many scenes MCI-24, MCI-40 and MCI-eq beat SCT under
   each metric (the thesis' claim: MCI-24/40 beat SCT in NMSE except on
   PERLUCE, yet show light bumps near the light);
3. the luminaires ranked by SCT's error under each metric (the paper's claim:
   ARCOS and PANOS look very good but score poorly).
"""
import argparse
import collections
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from atomic import emit_text  # noqa: E402
from results_io import load_records, matched  # noqa: E402

METRICS = ("nmse", "grad_nmse", "flip")
ORDER = ("SCT", "voronoi", "Delaunay+", "MCI-24", "MCI-40", "MCI-eq")


def label(r):
    """The seeds' name of a record's method, or None for the MCI curve and others."""
    p = r.get("params") or {}
    if matched(r):
        return "MCI-eq" if matched(r)[0] == "cubature" else None
    if r["method"] == "mc":
        return {24: "MCI-24", 40: "MCI-40"}.get(int(p.get("n", 0))) if r.get("role") != "mci_curve" else None
    if r["method"] == "voronoi":
        return "voronoi"
    if r["method"] == "cubature":
        if p.get("triangulation") == "delaunay":
            return "Delaunay+"
        if p.get("triangulation", "fan") == "fan" and p.get("dynamic", "cp") == "cp":
            return "SCT"
    return None


def short_lum(name):
    return name.split("_")[0].split(".")[0]


def gmean(v):
    v = [x for x in v if x is not None and x > 0 and math.isfinite(x)]
    return math.exp(sum(math.log(x) for x in v) / len(v)) if v else None


def amean(v):
    v = [x for x in v if x is not None and math.isfinite(x)]
    return sum(v) / len(v) if v else None


def fmt(x):
    return "-" if x is None else f"{x:.3g}"


def load(path):
    """scene (luminaire, height, rotation) -> label -> record"""
    scenes = collections.defaultdict(dict)
    for r in load_records(path):
        lab = label(r)
        if lab is not None:
            scenes[(short_lum(r["luminaire"]), r["height"], r["rotation"])][lab] = r
    return scenes


def regime(h):
    return "h 0.1" if h <= 0.11 else "h >= 1.1"


def means_table(scenes, labels):
    out = ["| luminaire | regime | metric | " + " | ".join(labels) + " |", "|---" * (3 + len(labels)) + "|"]
    lums = sorted({k[0] for k in scenes})
    for lum in lums:
        for g in ("h 0.1", "h >= 1.1"):
            keys = [k for k in scenes if k[0] == lum and regime(k[1]) == g]
            if not keys:
                continue
            for m in METRICS:
                mean = amean if m == "flip" else gmean
                cells = [fmt(mean([scenes[k][lab].get(m) for k in keys if lab in scenes[k]])) for lab in labels]
                out.append(f"| {lum} | {g} | {m} | " + " | ".join(cells) + " |")
    return out


def ratio_table(scenes, num, dens):
    """Per luminaire and regime: num's mean error over each of dens' (the means of means_table),
    per metric; above 1: num is worse."""
    out = ["| luminaire | regime | " + " | ".join(f"{num} / {d}: {m}" for d in dens for m in METRICS) + " |",
           "|---" * (2 + len(dens) * len(METRICS)) + "|"]
    for lum in sorted({k[0] for k in scenes}):
        for g in ("h 0.1", "h >= 1.1"):
            keys = [k for k in scenes if k[0] == lum and regime(k[1]) == g]
            if not keys:
                continue
            cells = []
            for d in dens:
                for m in METRICS:
                    mean = amean if m == "flip" else gmean
                    a = mean([scenes[k][num].get(m) for k in keys if num in scenes[k]])
                    b = mean([scenes[k][d].get(m) for k in keys if d in scenes[k]])
                    cells.append(fmt(a / b) if a is not None and b else "-")
            out.append(f"| {lum} | {g} | " + " | ".join(cells) + " |")
    return out


def beats_table(scenes, challengers, base, where, title):
    """Per luminaire and metric: in how many scenes (of those where both are defined) a challenger's
    error is below the base's. `where` filters the scenes."""
    out = [title, "", "| luminaire | " + " | ".join(f"{c} < {base}: {m}" for c in challengers for m in METRICS) + " |",
           "|---" * (1 + len(challengers) * len(METRICS)) + "|"]
    totals = collections.Counter()
    for lum in sorted({k[0] for k in scenes}) + ["all"]:
        cells = []
        for c in challengers:
            for m in METRICS:
                if lum == "all":
                    w, n = totals[(c, m, "w")], totals[(c, m, "n")]
                else:
                    w = n = 0
                    for k, d in scenes.items():
                        if k[0] != lum or not where(k) or c not in d or base not in d:
                            continue
                        a, b = d[c].get(m), d[base].get(m)
                        if a is None or b is None:
                            continue
                        n += 1
                        w += a < b
                    totals[(c, m, "w")] += w
                    totals[(c, m, "n")] += n
                cells.append(f"{w} / {n}")
        out.append(f"| {'**all**' if lum == 'all' else lum} | " + " | ".join(cells) + " |")
    return out


def rank_table(scenes, lab):
    """Luminaires ranked by `lab`'s mean error per metric (1: smallest error)."""
    lums = sorted({k[0] for k in scenes})
    score = {}
    for m in METRICS:
        mean = amean if m == "flip" else gmean
        score[m] = {lum: mean([d[lab].get(m) for k, d in scenes.items() if k[0] == lum and lab in d])
                    for lum in lums}
    rank = {m: {lum: i + 1 for i, lum in enumerate(sorted(lums, key=lambda x: (score[m][x] is None,
                                                                                 score[m][x] or 0)))}
            for m in METRICS}
    out = [f"| luminaire | " + " | ".join(f"{lab} {m} (rank)" for m in METRICS) + " |", "|---" * 4 + "|"]
    for lum in lums:
        out.append(f"| {lum} | " + " | ".join(f"{fmt(score[m][lum])} ({rank[m][lum]})" for m in METRICS) + " |")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results")
    ap.add_argument("--out")
    a = ap.parse_args()
    try:
        scenes = load(a.results)
    except (OSError, ValueError) as e:
        sys.exit(f"visual_claims: {e}")
    if not scenes:
        sys.exit(f"visual_claims: no records of the seeds' methods in {a.results}")
    labels = [lab for lab in ORDER if any(lab in d for d in scenes.values())]
    hs = sorted({k[1] for k in scenes})
    rs = sorted({k[2] for k in scenes})
    out = [f"{len(scenes)} scenes: {len({k[0] for k in scenes})} luminaires, heights "
           + ", ".join(f"{h:g}" for h in hs) + ", rotations " + ", ".join(f"{r:.4g}" for r in rs) + ".", ""]
    out += ["### Mean error per luminaire and regime", "",
            "Geometric mean over the regime's scenes (NMSE, grad_nmse), arithmetic mean (FLIP).", ""]
    out += means_table(scenes, labels)
    challengers = [c for c in ("MCI-24", "MCI-40", "MCI-eq") if c in labels]
    if "SCT" in labels and challengers:
        out += ["", "### SCT's error over MCI's", "",
                "The means above divided: above 1, SCT is worse. A metric that sees MCI's light bumps "
                "and not SCT's smooth bias gives a smaller ratio than NMSE near the light.", ""]
        out += ratio_table(scenes, "SCT", [c for c in challengers if c != "MCI-eq"] or challengers)
    for where, title in ((lambda k: True, "### MCI against SCT, every scene"),
                         (lambda k: k[1] <= 0.11, "### MCI against SCT near the light (h 0.1)")):
        out += [""] + beats_table(scenes, challengers, "SCT", where, title)
    out += ["", "### Luminaires ranked by SCT's error", ""] + rank_table(scenes, "SCT")
    emit_text("\n".join(out) + "\n", a.out)


if __name__ == "__main__":
    main()
