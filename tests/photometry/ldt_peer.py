#!/usr/bin/env python3
"""Peer check of lumibench's EULUMDAT reader against pyldt (PyPI eulumdat-py, MIT).

Usage: ldt_peer.py LUMIBENCH FILE.ldt [FILE.ldt ...]

For every file, every node (gamma, C) of the angle grid the file declares is
evaluated twice: by pyldt (its symmetry-expanded matrix in cd/klm times the
summed lamp flux / 1000) and by `lumibench luminaire eval` (absolute cd).
Prints one line per file with the worst difference relative to the file's
maximum candela and exits 1 if any file exceeds the tolerance, 2 if pyldt is
missing (the caller skips then).

Tolerance 1e-6 of max cd: both readers parse the same decimals; lumibench
prints 9 significant digits (<= 5e-9 relative) and its bilinear lookup at a
node is exact up to rounding, so 1e-6 leaves two orders of magnitude of room
while a misplaced plane differs by a whole plane's contrast (71 % of max cd
for the Isym 3 mirror of LINETIK-S).
"""
import subprocess
import sys

TOLERANCE = 1e-6


def main(argv):
    try:
        from pyldt import LdtReader
    except ImportError as e:
        print(f"pyldt is not importable: {e}", file=sys.stderr)
        return 2
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    binary, files = argv[1], argv[2:]
    worst_all = 0.0
    failed = []
    for path in files:
        ldt = LdtReader.read(path)
        h = ldt.header
        scale = sum(h.lamp_flux) / 1000.0
        # Isym 1 may list no C angle (Nc = 0): one plane for every C.
        c_angles = h.c_angles if h.mc > 0 else [0.0]
        rows = ldt.intensities if h.mc > 0 else [ldt.intensities[0]]
        args, expected = [], []
        for ic, c in enumerate(c_angles):
            for ig, g in enumerate(h.g_angles):
                args += [repr(float(g)), repr(float(c))]
                expected.append(rows[ic][ig] * scale)
        out = subprocess.run([binary, "luminaire", "eval", path, *args], capture_output=True, text=True)
        if out.returncode != 0:
            print(f"{path}: lumibench luminaire eval failed ({out.returncode}): {out.stderr.strip()}")
            failed.append(path)
            continue
        got = [float(x) for x in out.stdout.split()]
        if len(got) != len(expected):
            print(f"{path}: expected {len(expected)} values from lumibench, got {len(got)}")
            failed.append(path)
            continue
        peak = max(max(expected), 1e-300)
        worst, where = 0.0, None
        for k, (a, b) in enumerate(zip(got, expected)):
            d = abs(a - b) / peak
            if d > worst:
                worst, where = d, k
        worst_all = max(worst_all, worst)
        detail = ""
        if where is not None:
            g, c = args[2 * where], args[2 * where + 1]
            detail = f" at gamma {g} C {c}: lumibench {got[where]:.6g} cd, pyldt {expected[where]:.6g} cd"
        status = "ok" if worst <= TOLERANCE else "MISMATCH"
        print(f"{status} {path}: Isym {h.isym}, {len(expected)} nodes, worst {worst:.2e} of max cd{detail}")
        if worst > TOLERANCE:
            failed.append(path)
    print(f"{len(files) - len(failed)} of {len(files)} files agree with pyldt within {TOLERANCE:g} of max cd "
          f"(worst {worst_all:.2e})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
