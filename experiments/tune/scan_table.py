#!/usr/bin/python3
"""The parameter scans of docs/tuning.md: their experiment files and their tables.

Tables (default): from `lumibench run` results of the scan experiments
(experiments/tune-{plane,area,dense,joint}-scan.json; committed as
experiments/tune/tune-*-scan-results.csv.xz): per spec, on how many of the 20 luminaires
its geometric mean NMSE over the luminaire's scenes beats robust's (better, equal), the
geometric mean over the 19 luminaires other than the pencil of that ratio, the worst
ratio, and the luminaires where it loses. A luminaire's scenes are those where robust's
NMSE is defined (a black reference leaves it undefined); a spec's undefined or
non-finite NMSE on one of them counts as a loss. The pencil's dust scenes count here as
any other (so area_q / area_sin can "beat" robust on them); --cover ties them.

--cover: what the whole scanned set can reach: the most luminaires one spec beats, the
specs that reach it, per luminaire how many specs beat robust there and the most
luminaires any of those beats, and leave-one-luminaire-out over the scan: each fold picks
a spec on the other 19 luminaires by each rule of RULES (the tuner's `geomean` objective
searched exhaustively over the scan; the most luminaires beaten, ties broken two ways) and
scores it on the 20th. The pencil's references are float dust (its NMSE 1e9-1e30 measures
no method, and area_q / area_sin move it by orders of magnitude): it is a tie for every
spec and left out of the picks (--dust '' keeps it).

--make dense|fine|joint|res32: write the experiment file of a scan (the 20 luminaires and the
scenes of experiments/tune-plane-scan.json, resp. tune-area-scan.json): dense is
corner_inset 0 .. 1 step 0.025 x dyn_weight 0 .. 4 step 0.2 on the plane-crossing scene,
fine its best band (corner_inset 0.6 .. 1 step 0.0125 x dyn_weight 0.6 .. 1.2 step 0.025),
res32 corner_inset 0 .. 1 step 0.1 x dyn_weight 0 .. 2 step 0.1 at 32 x 32 on the four scenes
that include those where they act at that resolution;
joint is area_q, area_sin, corner_inset, dyn_weight at scrambled Sobol points (seed 1)
over the tunables table's ranges and over a box around robust's defaults, on six scenes.

--plot PNG: the dense scan's map (luminaires beaten per point; where each luminaire the
best points lose on is beaten).

usage: experiments/tune/scan_table.py [--cover] [RESULTS.csv[.xz] ...]
       experiments/tune/scan_table.py --plot PNG DENSE-RESULTS.csv[.xz]
       experiments/tune/scan_table.py --make dense|fine|joint|res32 [--points N] --out EXP.json"""
import argparse
import collections
import csv
import io
import json
import lzma
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXPERIMENTS = os.path.dirname(HERE)


def load(path):
    """{series: {luminaire: {scene: nmse}}} of the method records (nan where undefined)."""
    op = lzma.open if path.endswith(".xz") else open
    with op(path, "rt") as f:
        rows = list(csv.DictReader(io.StringIO(f.read())))
    nm = collections.defaultdict(lambda: collections.defaultdict(dict))
    for r in rows:
        if r["role"] != "method":
            continue
        try:
            v = float(r["nmse"])
        except ValueError:
            v = float("nan")
        nm[r["series"]][r["luminaire"].split("/")[-1]][r["scene"]] = v
    return nm


def defined(v):
    return math.isfinite(v) and v > 0


DUST = ("pencil",)


def log_ratios(nm, dust=DUST):
    """{series: {luminaire: mean over its scenes of log(NMSE / robust's NMSE)}} (inf: a loss),
    and per luminaire its scenes. A luminaire whose name contains a word of `dust` is a tie
    for every spec and has no scenes (its references are float dust: its NMSE measures no
    method)."""
    rob = nm["robust"]
    scenes = {lum: [s for s, v in d.items() if defined(v) and not any(w in lum for w in dust)]
              for lum, d in rob.items()}
    out = {}
    for series, d in nm.items():
        lr = {}
        for lum, ss in scenes.items():
            vals = [d[lum].get(s, float("nan")) for s in ss]
            lr[lum] = (0.0 if not ss else
                       sum(math.log(v / rob[lum][s]) for v, s in zip(vals, ss)) / len(ss)
                       if all(defined(v) for v in vals) else float("inf"))
        out[series] = lr
    return out, scenes


def short(lum):
    return lum.split(".")[0][:10]


def table(path):
    lr, _ = log_ratios(load(path), dust=())
    out = []
    for s, d in lr.items():
        if s == "robust":
            continue
        g = {lum: math.exp(v) for lum, v in d.items()}
        others = [v for lum, v in d.items() if "pencil" not in lum]
        out.append((sum(v < 1 for v in g.values()), sum(v == 1 for v in g.values()),
                    math.exp(sum(others) / len(others)), max(g.values()), s,
                    [short(lum) for lum in g if g[lum] > 1]))
    print(f"\n{os.path.basename(path)}\n")
    print("| spec | better than robust | equal | geomean ratio (19, no pencil) | worst ratio | loses on |")
    print("|---|---|---|---|---|---|")
    for w, e, gm, mx, s, lo in sorted(out, key=lambda x: (-x[0], x[2])):
        print(f"| `{s}` | {w} | {e} | {gm:.4f} | {mx:.3f} | {', '.join(lo)} |")


RULES = {
    "geomean": "lowest mean log NMSE over the other 19 luminaires' scenes (the tuner's objective)",
    "count": "most of the 19 beaten, ties by the former",
    "count-worst": "most of the 19 beaten, ties by the smallest worst ratio among the 19",
}


def fold_pick(nm, lr, scenes, specs, held, by):
    """The spec a search over `specs` on every luminaire but `held` ends at, by the rule
    `by` (RULES); robust itself (no change) wins ties."""
    def objective(s):
        v = [math.log(nm[s][lum][sc]) if defined(nm[s][lum].get(sc, float("nan"))) else 1e300
             for lum, ss in scenes.items() if lum != held for sc in ss]
        return sum(v) / len(v)

    def key(s):
        wins = sum(v < 0 for lum, v in lr[s].items() if lum != held)
        worst = max(v for lum, v in lr[s].items() if lum != held)
        return {"geomean": (objective(s),), "count": (-wins, objective(s)),
                "count-worst": (-wins, worst)}[by] + (s != "robust",)

    return min(specs, key=key)


def cover(path, dust=DUST):
    nm = load(path)
    lr, scenes = log_ratios(nm, dust)
    specs = [s for s in lr if s != "robust"]
    lums = list(lr["robust"])
    beats = {s: {lum for lum in lums if lr[s][lum] < 0} for s in specs}
    best = max(len(b) for b in beats.values())
    print(f"\n{os.path.basename(path)}: {len(specs)} specs besides robust, {len(lums)} luminaires, "
          f"{sum(len(v) for v in scenes.values())} scenes with robust's NMSE defined"
          + (f" (float dust, a tie for every spec, no scene counted: {', '.join(short(l) for l in lums if not scenes[l])})"
             if any(not v for v in scenes.values()) else "") + "\n")
    hist = collections.Counter(len(b) for b in beats.values())
    print("luminaires beaten by one spec: count of specs: " +
          ", ".join(f"{k}: {hist[k]}" for k in sorted(hist, reverse=True)))
    top = sorted(specs, key=lambda s: (-len(beats[s]), sum(lr[s][lum] for lum in lums if "pencil" not in lum)))
    print(f"\nmost luminaires beaten by one spec: {best} of {len(lums)}; the first of those specs "
          "(by geomean ratio over the 19 without the pencil):\n")
    print("| spec | beaten | geomean ratio (19) | loses or ties on |\n|---|---|---|---|")
    for s in top[:8]:
        g = math.exp(sum(lr[s][lum] for lum in lums if "pencil" not in lum) / (len(lums) - 1))
        print(f"| `{s}` | {len(beats[s])} | {g:.4f} | {', '.join(short(l) for l in lums if l not in beats[s])} |")
    print("\nper luminaire: specs beating robust there, its best ratio, and the most luminaires "
          "beaten by any of those specs\n")
    print("| luminaire | specs beating robust | best ratio | most beaten by one of them |\n|---|---|---|---|")
    for lum in lums:
        b = [s for s in specs if lum in beats[s]]
        r = min(math.exp(lr[s][lum]) for s in specs)
        print(f"| {short(lum)} | {len(b)} of {len(specs)} | {r:.4f} | {max((len(beats[s]) for s in b), default=0)} |")
    union = {lum for b in beats.values() for lum in b}
    print(f"\nluminaires beaten by at least one spec: {len(union)} of {len(lums)} "
          f"(never: {', '.join(short(l) for l in lums if l not in union) or 'none'})")
    picks = {by: {held: fold_pick(nm, lr, scenes, specs + ["robust"], held, by) for held in lums} for by in RULES}
    won = {by: [h for h in lums if p[h] != "robust" and lr[p[h]][h] < 0] for by, p in picks.items()}
    print("\nleave-one-out over the scan: each fold picks a spec on the other 19 luminaires and is scored on "
          "the 20th; folds whose pick beats robust there:\n")
    for by, text in RULES.items():
        print(f"- {by} ({text}): {len(won[by])} of {len(lums)}")
    print("\n| held out | " + " | ".join(f"pick by {by} | held-out ratio" for by in RULES) + " |")
    print("|---" * (1 + 2 * len(RULES)) + "|")
    for h in lums:
        print(f"| {short(h)} | " + " | ".join(f"`{picks[by][h]}` | {math.exp(lr[picks[by][h]][h]):.4f}"
                                             for by in RULES) + " |")

def params_of(series):
    """{name: value} of a scan spec `robust:k=v,...` (robust's own point: {})."""
    rest = series.partition(":")[2]
    return {k: float(v) for k, v in (kv.split("=") for kv in rest.split(",") if kv)}


def plot(path, out):
    """The dense scan as a map: per (corner_inset, dyn_weight) the luminaires beaten, and
    where each luminaire that the best specs lose on is beaten."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lr, _ = log_ratios(load(path))
    pts = {s: params_of(s) for s in lr if s.startswith("robust:")}
    ci = sorted({p["corner_inset"] for p in pts.values()})
    dw = sorted({p["dyn_weight"] for p in pts.values()})
    grid = {(p["corner_inset"], p["dyn_weight"]): s for s, p in pts.items()}
    grid.setdefault((0.0, 1.0), "robust")
    cells = [(c, d) for c in ci for d in dw if (c, d) in grid]
    wins = {cd: sum(v < 0 for v in lr[grid[cd]].values()) for cd in cells}
    count = [[wins.get((c, d), float("nan")) for c in ci] for d in dw]
    best = max(wins.values())
    hard = [lum for lum in lr["robust"] if "pencil" not in lum and
            all(lr[grid[cd]][lum] >= 0 for cd in cells if wins[cd] == best)]
    fig, ax = plt.subplots(figsize=(7.5, 5))
    im = ax.pcolormesh(ci, dw, count, shading="nearest", cmap="viridis", vmin=0, vmax=20)
    fig.colorbar(im, ax=ax, label="luminaires where the spec beats robust (of 20)")
    step = (ci[1] - ci[0]) / 4 if len(ci) > 1 else 0
    for k, (lum, mk, col) in enumerate(zip(hard, "oxs+d^v", ("white", "red", "orange", "magenta", "cyan", "k"))):
        pts_l = [(c + (k - 1.5) * step, d) for c, d in cells if lr[grid[(c, d)]][lum] < 0]
        ax.scatter([x for x, _ in pts_l], [y for _, y in pts_l], marker=mk, s=10, color=col,
                   label=f"beats robust on {short(lum)} ({len(pts_l)})")
    ax.plot([0], [1], "k*", ms=14, label="robust")
    ax.plot([0.8625], [0], "wP", ms=11, mec="k", label="tuned")
    ax.set_xlabel("corner_inset")
    ax.set_ylabel("dyn_weight")
    ax.set_title(f"{os.path.basename(path)}: most beaten by one spec {best} of 20", fontsize=9)
    ax.legend(fontsize=7, loc="upper right", framealpha=0.8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"{out}: map of {len(pts)} specs")


def fmt(x):
    return f"{x:.4g}"


def make(kind, points, out):
    base = json.load(open(os.path.join(EXPERIMENTS, f"tune-{'plane' if kind in ('dense', 'fine') else 'area'}-scan.json")))
    methods = ["robust", "tuned"]
    if kind == "fine":
        base["description"] = (
            "docs/tuning.md: the dense scan's best band refined: robust's corner_inset 0.6 .. 1 step 0.0125 x "
            "dyn_weight 0.6 .. 1.2 step 0.025 on the plane-crossing scene (h 0.1, R pi/2), all 20 luminaires "
            "of tune-all-cv-*.json, 16 x 16 error images. Written by experiments/tune/scan_table.py --make fine.")
        methods += [f"robust:corner_inset={fmt(0.6 + i / 80)},dyn_weight={fmt(0.6 + j / 40)}"
                    for i in range(33) for j in range(25)]
    elif kind == "res32":
        base["description"] = (
            "docs/tuning.md: robust's corner_inset (0 .. 1 step 0.1) x dyn_weight (0 .. 2 step 0.1) at 32 x 32 "
            "error images on the scenes of tune-all-cv-*.json where they act at that resolution (h 0.1, R pi/2 "
            "and 3pi/4; h 1.1, R pi/2; h 1.1, R 3pi/4 as a check that it does not move), all 20 luminaires. "
            "Written by experiments/tune/scan_table.py --make res32.")
        base["heights"], base["rotations"] = [0.1, 1.1], ["pi/2", "3pi/4"]
        base["res"] = base["time_res"] = 32
        methods += [f"robust:corner_inset={fmt(i / 10)},dyn_weight={fmt(j / 10)}" for i in range(11) for j in range(21)]
    elif kind == "dense":
        base["description"] = (
            "docs/tuning.md: robust's corner_inset (0 .. 1 step 0.025) x dyn_weight (0 .. 4 step 0.2) on "
            "the plane-crossing scene (h 0.1, R pi/2; the only one of the six where they act at robust's "
            "area_q / area_sin), all 20 luminaires of tune-all-cv-*.json, 16 x 16 error images. Written by "
            "experiments/tune/scan_table.py --make dense; its --cover counts per spec the luminaires "
            "it beats robust on.")
        methods += [f"robust:corner_inset={fmt(i / 40)},dyn_weight={fmt(j / 5)}" for i in range(41) for j in range(21)]
    else:
        from scipy.stats import qmc
        base["description"] = (
            "docs/tuning.md: robust's area_q, area_sin, corner_inset, dyn_weight jointly at scrambled "
            "Sobol points (seed 1): half over the tunables table's ranges (area_q 0.1 .. 10 log, area_sin "
            "0 .. 1, corner_inset 0 .. 1, dyn_weight 0 .. 4), half over area_q 0.35 .. 0.7 (log), area_sin "
            "0.35 .. 0.7 and the same corner_inset / dyn_weight; plus three corner_inset / dyn_weight "
            "points at robust's area_q / area_sin (which scenes they change). All six scenes per "
            "luminaire of tune-all-cv-*.json, 20 luminaires, 16 x 16 error images. Written by "
            "experiments/tune/scan_table.py --make joint.")
        methods += ["robust:corner_inset=0,dyn_weight=4", "robust:corner_inset=1,dyn_weight=0",
                    "robust:corner_inset=0.5,dyn_weight=2.6"]
        for box, seed in (((0.1, 10.0, 0.0, 1.0), 1), ((0.35, 0.7, 0.35, 0.7), 2)):
            qlo, qhi, slo, shi = box
            for u in qmc.Sobol(d=4, scramble=True, seed=seed).random(points // 2):
                q = qlo * (qhi / qlo) ** u[0]
                methods.append(f"robust:area_q={fmt(q)},area_sin={fmt(slo + (shi - slo) * u[1])},"
                               f"corner_inset={fmt(u[2])},dyn_weight={fmt(4 * u[3])}")
    base["name"] = f"tune-{kind}-scan"
    base["methods"] = methods
    with open(out + ".tmp", "w") as f:
        json.dump(base, f, indent=2)
        f.write("\n")
    os.replace(out + ".tmp", out)
    print(f"{out}: {len(methods)} methods")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", nargs="*")
    ap.add_argument("--cover", action="store_true")
    ap.add_argument("--dust", default=",".join(DUST),
                    help="with --cover: comma-separated words naming luminaires whose references are float "
                         "dust: a tie for every spec, left out of the picks (default pencil; '' keeps them)")
    ap.add_argument("--make", choices=("dense", "fine", "joint", "res32"))
    ap.add_argument("--points", type=int, default=256)
    ap.add_argument("--plot", metavar="PNG", help="with one dense-scan RESULTS: its map")
    ap.add_argument("--out")
    a = ap.parse_args()
    if a.make:
        if not a.out:
            sys.exit("scan_table.py: --make needs --out EXP.json")
        make(a.make, a.points, a.out)
        return
    paths = a.results or [os.path.join(HERE, f"tune-{k}-scan-results.csv.xz") for k in ("plane", "area")]
    if a.plot:
        plot(paths[0], a.plot)
        return
    for p in paths:
        if a.cover:
            cover(p, tuple(w for w in a.dust.split(",") if w))
        else:
            table(p)


if __name__ == "__main__":
    main()
