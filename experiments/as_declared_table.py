#!/usr/bin/env python3
"""The tables of docs/studies/as-declared.md from the two runs of experiments/as-declared.json
and experiments/as-declared-normalised.json (result directories or .json.xz files):

    experiments/as_declared_table.py DECLARED NORMALISED

Per luminaire and light (declared / normalised): the geometric-mean NMSE of each
method over the scenes, and the equal-time verdicts (wins / ties / losses, 8 seeds)
of the cubature and robust against MCI; then the totals and, per method, the
scenes where a method is more than 10x worse than the point light."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plots"))
import results_io  # noqa: E402

METHODS = ["point", "cp", "structured", "cubature", "robust"]


def scene_of(r):
    return (r["luminaire"], r["height"], r["rotation"])


def summarise(recs):
    """{luminaire: {"shape", "size", method: [nmse...], "verdicts": {method: [..]}}}"""
    out, own = {}, {}
    for r in recs:
        if results_io.equal_time(r) is None:
            own[(scene_of(r), r["method"])] = r
    for r in recs:
        lum = r["luminaire"]
        d = out.setdefault(lum, {"shape": r.get("shape", "rect"), "size": r.get("size", [1, 1]), "verdicts": {}})
        m = results_io.matched(r)
        if m is not None:
            meth = own.get((scene_of(r), m[0]))
            if meth is not None:
                d["verdicts"].setdefault(m[0], []).append(results_io.verdict(meth, r))
        elif r["method"] in METHODS and r.get("nmse") is not None:
            d.setdefault(r["method"], []).append((scene_of(r), r["nmse"]))
    return out


def geomean(xs):
    xs = [x for x in xs if x is not None and x > 0]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else float("nan")


def wtl(vs):
    return "{}/{}/{}".format(vs.count("win"), vs.count("tie"), vs.count("loss"))


def short(lum):
    return os.path.basename(lum).split("_")[0][:10]


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    dec, nor = (summarise(results_io.load_records(p)) for p in argv[1:])
    print("| luminaire | light | " + " | ".join(METHODS) + " | cubature vs MCI | robust vs MCI |")
    print("|---|---|" + "---|" * (len(METHODS) + 2))
    tot = {}
    for lum in dec:
        for tag, s in (("declared", dec[lum]), ("1 x 1", nor.get(lum))):
            if s is None:
                continue
            light = "{} {:g} x {:g}".format(s["shape"], *s["size"]) if tag == "declared" else "rect 1 x 1"
            cells = ["{:.3g}".format(geomean([v for _, v in s.get(m, [])])) for m in METHODS]
            vc, vr = s["verdicts"].get("cubature", []), s["verdicts"].get("robust", [])
            for k, v in (("cubature", vc), ("robust", vr)):
                tot.setdefault((tag, k), []).extend(v)
            print("| {} | {} | {} | {} | {} |".format(short(lum), light, " | ".join(cells), wtl(vc), wtl(vr)))
    print()
    for (tag, k), v in sorted(tot.items()):
        print("- {} {}: {} (wins / ties / losses of {} scenes)".format(tag, k, wtl(v), len(v)))
    print()
    for tag, runs in (("declared", dec), ("1 x 1", nor)):
        for m in METHODS[1:]:
            bad = []
            for lum, s in runs.items():
                pt = dict(s.get("point", []))
                for sc, v in s.get(m, []):
                    if sc in pt and pt[sc] > 0 and v > 10 * pt[sc]:
                        bad.append("{} h {:g} R {:.3g}".format(short(lum), sc[1], sc[2]))
            if bad:
                print("- {}: {} more than 10x the point light's NMSE in {} scenes: {}".format(
                    tag, m, len(bad), ", ".join(bad[:12]) + (" ..." if len(bad) > 12 else "")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
