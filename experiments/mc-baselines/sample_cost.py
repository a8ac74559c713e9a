#!/usr/bin/env python3
"""Cost per sample of mc specs (docs/mc-baselines.md): (t(64) - t(8)) / 56 from
`lumibench render --reps 7` medians, rounds interleaved spec by spec, the
median over the rounds; the first spec is the yardstick (x column). ARCOS3 at
h 1.1, R 3pi/4. LUMIBENCH_KERNEL_DIR selects another kernel directory (e.g. a
copy with a changed constant) as for every lumibench run.

usage: sample_cost.py RES ROUNDS SPEC [SPEC ...]   (SPEC: mc keys without n, e.g. domain=solid)
"""
import os
import statistics
import sys
import tempfile

from lbrun import ZUMTOBEL, render

LUM = os.path.join(ZUMTOBEL, "ARCOS3_60712332.LDT")


def main():
    if len(sys.argv) < 4 or not sys.argv[1].isdigit() or not sys.argv[2].isdigit():
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        sys.exit(2)
    res, rounds, specs = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3:]
    out = os.path.join(tempfile.mkdtemp(prefix="mccost"), "c.exr")
    t = lambda spec, n: render(LUM, 1.1, "3pi/4", f"mc:n={n},{spec}", res, out, reps=7)["time_ms"]["median"]
    data = {s: [] for s in specs}
    for _ in range(rounds):
        for s in specs:
            a, b = t(s, 8), t(s, 64)
            data[s].append((a, (b - a) / 56))
    base = statistics.median(x[1] for x in data[specs[0]])
    for s in specs:
        ps = [x[1] for x in data[s]]
        print(f"{s:<52} {statistics.median(ps):8.4f} ms/sample ({', '.join(f'{v:.3f}' for v in ps)})  "
              f"x{statistics.median(ps) / base:6.2f}  t(8) {statistics.median(x[0] for x in data[s]):7.2f} ms")


if __name__ == "__main__":
    main()
