#!/usr/bin/env python3
"""Equal-time verdicts of an mc-baselines results file (lumibench run; .json or
.json.xz) in NMSE and FLIP, with the pairs off equal time counted apart.

A pair (a method and its MC partner on one scene) is *on time* where the
partner's paired time ratio lies within the run's tolerance (the record's
equal_time.ratio, +-10 %); off-time pairs are counted as such and not as wins,
ties or losses (their verdicts are listed apart, for what they are: against an MC that ran
longer or shorter). An off-time pair whose MC at N = 1 took longer than the method
is at the *N = 1 floor*: one sample per pixel plus the filter
already costs more than the method, no N gives an equal-time partner; in a run
with equal_time_subpixel the search goes below one sample per pixel (mc's
scale), and the floor is its least scale (0.05). The MC column gives the mean
samples per image pixel (equal_time.n: (N + extra) scale^2), and how many pairs
were below one. On-time verdicts as results::verdict: a win where the method's
value (its 95 % interval where it has one) lies below the partner's interval, a
loss where above, else a tie.

    python3 experiments/mc-baselines/filter_verdicts.py RESULTS [--json OUT]

Prints one markdown table; --json writes the counts (atomically).
"""
import argparse
import json
import lzma
import math
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                                "plots"))
from results_io import verdict  # noqa: E402  (results::verdict in Python)


MIN_SCALE = 0.05  # mc's least scale (methods::kMinScale)


def load(path):
    opener = lzma.open if path.endswith(".xz") else open
    with opener(path, "rt") as f:
        return json.load(f)


def at_floor(r, et):
    """The partner at N = 1, or its N = 1 candidate, took longer than the method
    (beyond the tolerance): the loaded machine can time N = 2 below N = 1, and
    the runner keeps the candidate nearest equal time."""
    tol = et.get("tolerance", 0.1)
    cands = et.get("candidates", [])
    if any("scale" in c for c in cands):  # below N = 1: the floor is the least scale
        return any(c.get("scale", 1) <= MIN_SCALE + 1e-9 and c["ratio"] > 1 + tol for c in cands)
    if r.get("n", et.get("n")) == 1:
        return True
    return any(c.get("n") == 1 and "extra" not in c and c["ratio"] > 1 + tol for c in cands)


def tally(doc):
    methods = {(r["scene"], r["spec"]): r for r in doc["records"] if r["role"] == "method"}
    rows = {}
    for r in doc["records"]:
        if r["role"] != "equal_time":
            continue
        et = r["equal_time"]
        m = methods.get((r["scene"], et["label"]))
        if m is None:
            continue
        row = rows.setdefault(et["label"], {"pairs": 0, "off_time": 0, "nmse": {}, "flip": {}, "off_nmse": {}, "off_flip": {},
                                            "ratios": [], "n": [], "log_nmse": [], "floor": 0, "below_one": 0})
        row["pairs"] += 1
        row["ratios"].append(et["ratio"])
        row["n"].append(et.get("n", r.get("n")))
        row["below_one"] += et.get("scale", 1) < 1
        off = abs(et["ratio"] - 1) > et.get("tolerance", 0.1)
        row["off_time"] += off
        row["floor"] += off and et["ratio"] > 1 and at_floor(r, et)
        for metric in ("nmse", "flip"):
            v = verdict(m, r, metric)
            key = "off_" + metric if off else metric
            row.setdefault(key, {})[v] = row.setdefault(key, {}).get(v, 0) + 1
        if off:
            continue
        if m["nmse"] > 0 and r["nmse"] > 0:
            row["log_nmse"].append(math.log(m["nmse"] / r["nmse"]))
    return rows


def wtl(d):
    return f"{d.get('win', 0)} / {d.get('tie', 0)} / {d.get('loss', 0)}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results")
    ap.add_argument("--json", help="write the counts here")
    a = ap.parse_args()
    rows = tally(load(a.results))
    print("| method | pairs | off-time (at the floor) | NMSE wins / ties / losses | FLIP wins / ties / losses "
          "| NMSE / MC's (geo. mean, on time) | MC samples per pixel (pairs below 1) | MC time / method time, median (range) "
          "| off-time pairs: NMSE, FLIP w / t / l |")
    print("|---|---|---|---|---|---|---|---|---|")
    out = {}
    for label, r in rows.items():
        geo = math.exp(statistics.mean(r["log_nmse"])) if r["log_nmse"] else float("nan")
        ns = [n for n in r["n"] if n is not None]
        print(f"| {label} | {r['pairs']} | {r['off_time']} ({r['floor']}) | {wtl(r['nmse'])} | {wtl(r['flip'])} | {geo:.3g} "
              f"| {min(ns):.2g}-{max(ns):.3g} ({r['below_one']}) | {statistics.median(r['ratios']):.2f} "
              f"({min(r['ratios']):.2f}-{max(r['ratios']):.2f}) | {wtl(r['off_nmse'])}, {wtl(r['off_flip'])} |")
        out[label] = {k: v for k, v in r.items() if k != "log_nmse"}
        out[label]["nmse_ratio_geomean"] = geo
    if a.json:
        d = os.path.dirname(os.path.abspath(a.json))
        fd, tmp = tempfile.mkstemp(dir=d, prefix=".filter_verdicts.")
        with os.fdopen(fd, "w") as f:
            json.dump({"results": a.results, "verdicts": out}, f, indent=1)
        os.replace(tmp, a.json)


if __name__ == "__main__":
    sys.exit(main())
