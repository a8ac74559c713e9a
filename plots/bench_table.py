#!/usr/bin/env python3
"""Markdown tables from `lumibench bench --json` documents (docs/performance.md).

Usage: python3 plots/bench_table.py RUN.json [RUN.json ...] [-- RUN.json ...] ...

Runs separated by `--` form groups (e.g. one device and resolution each). Prints
one line of ratios per run, then, from the median run of each group (by the
cubature / MC 8 ratio), the quantity table and the per-method table, with one
column (or pair of columns) per group, side by side. Method rows are the union
of the groups' method names (JSON `methods[].method`); "-" where a group's run
has no such row. Standard library only.
"""
import json
import statistics
import sys


def num(x):
    """Three significant figures without exponents for the usual ranges."""
    if x >= 100:
        return f"{x:.0f}"
    if x >= 10:
        return f"{x:.1f}"
    if x >= 1:
        return f"{x:.2f}"
    return f"{x:.3g}"


def mc_curve(fit):
    """MC's t(N): the line the run carries (t0_ms, ms_per_sample), else its points."""
    if "t0_ms" in fit:
        return f"{num(fit['t0_ms'])} ms + {num(fit['ms_per_sample'])} ms per sample"
    return ", ".join(f"t({n}) = {num(t)} ms" for n, t in fit["points"])


def groups_of(args):
    groups, cur = [], []
    for a in args:
        if a == "--":
            if cur:
                groups.append(cur)
            cur = []
        else:
            cur.append(a)
    if cur:
        groups.append(cur)
    return groups


def load(path):
    try:
        with open(path) as f:
            d = json.load(f)
        d["mc"]["ratio"], d["cubature"]["ratio"], d["methods"]  # the fields the tables need
        return d
    except (OSError, ValueError, KeyError, TypeError) as e:
        sys.exit(f"{path}: not a `lumibench bench --json` document ({e})")


def median_run(runs):
    med = statistics.median_low([d["cubature"]["ratio"] for _, d in runs])
    return next(r for r in runs if r[1]["cubature"]["ratio"] == med)


def main():
    groups = groups_of(sys.argv[1:])
    if not groups:
        sys.exit("usage: bench_table.py RUN.json [RUN.json ...] [-- RUN.json ...] ...")
    meds = []
    for g in groups:
        runs = [(p, load(p)) for p in g]
        for path, d in runs:
            print(f"- {path}: MC / naive {d['mc']['ratio']:.1f}, cubature / MC 8 {d['cubature']['ratio']:.2f}, "
                  f"equal-time N {d['cubature']['equal_time_n']}, commit "
                  f"{d.get('context', {}).get('commit', '?')[:8]}")
        meds.append(median_run(runs))
    print("\nMedian run" + ("s" if len(meds) > 1 else "") + ": " + ", ".join(p for p, _ in meds) + "\n")
    ds = [d for _, d in meds]

    def row(label, cells):
        print(f"| {label} | " + " | ".join(cells) + " |")

    print("| quantity | " + " | ".join(f"{d['device']} ({d['res']}^2)" for d in ds) + " |")
    print("|---|" + "---|" * len(ds))
    row("driver", [d["driver"] for d in ds])
    row("naive MC samples/s (N = 32)" if all(d["mc"]["n"] == 32 for d in ds) else "naive MC samples/s",
        [f"{d['mc']['naive_sps']:.2g}" for d in ds])
    row("fast MC samples/s", [f"{d['mc']['fast_sps']:.2g}" for d in ds])
    row("ratio fast / naive (target >= 10)",
        [f"**{d['mc']['ratio']:.1f}** ({'met' if d['mc']['ok'] else 'missed'})" for d in ds])
    row("cubature / MC 8 time (target <= 1)",
        [f"**{d['cubature']['ratio']:.2f}** ({'met' if d['cubature']['ok'] else 'missed'})" for d in ds])
    row("cubature's equal-time MC N",
        [f"{d['cubature']['equal_time_n']} (t = {num(d['cubature']['verify_ms'])} ms vs "
         f"{num(d['cubature']['time_ms'])} ms)" for d in ds])
    row("MC t(N) fit", [mc_curve(d["mc_fit"]) for d in ds])
    # the fair-equal-time goals (runs that have them; "-" elsewhere)
    goals = []
    for d in ds:
        for g in d.get("goals", []):
            if g["name"] not in [x["name"] for x in goals]:
                goals.append(g)
    for g in goals:
        cells = []
        for d in ds:
            m = next((x for x in d.get("goals", []) if x["name"] == g["name"]), None)
            cells.append(f"**{m['ratio']:.2f}** ({'met' if m['ok'] else 'missed'})" if m else "-")
        row(f"{g['name']} (target <= {g['target']:g})", cells)

    names = []
    for d in ds:
        for m in d["methods"]:
            if m["method"] not in names:
                names.append(m["method"])
    print("\n| method | " + " | ".join(f"{d['device']} {d['res']}^2: ms | ns / pixel" for d in ds) + " |")
    print("|---|" + "---|---|" * len(ds))
    for n in names:
        cells = []
        for d in ds:
            m = next((m for m in d["methods"] if m["method"] == n), None)
            cells += [num(m["time_ms"]), num(m["ns_per_pixel"])] if m else ["-", "-"]
        row(n, cells)


if __name__ == "__main__":
    main()
