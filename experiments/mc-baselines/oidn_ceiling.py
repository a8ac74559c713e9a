#!/usr/bin/env python3
"""Intel Open Image Denoise as a quality ceiling beside the suite's OpenCL
filters (docs/mc-baselines.md). The strongest MC (solid angle, Owen-scrambled
Sobol per pixel) at N samples is rendered at the timing resolution, then
filtered four ways: the kernels' own `denoise=gauss16` and `denoise=atrous`
(timed with the render on the device), and on the host by OIDN's `RT` filter
(HDR) and its `RTLightmap` filter (the image is an irradiance map). A filter
works in pixels, so every error is measured at the resolution it runs at,
against the reference rendered there. OIDN's time is host time (median of 5
after a warm-up), flagged as such; it is not comparable with the device
times.

Renders with build/lumibench (argument lists, no shell). Writes JSON
atomically to OUT after every scene (a rerun starts over) and a markdown table
to stdout.

Needs pyoidn and OpenEXR in .venv: scripts/install-deps.sh --oidn.

usage: oidn_ceiling.py OUT.json [--res 512] [--seeds 2] [--ns 1,2,4]
                       [--luminaires ARCOS3,PANOS] [--scenes 0.1:pi/2,1.1:3pi/4]
"""
import argparse
import math
import os
import statistics
import sys
import tempfile
import time

from lbrun import ZUMTOBEL as LUMDIR, nmse, parse_scenes, render, write_json
MC = "mc:domain=solid,sequence=sobol"
DEVICE_FILTERS = ["none", "gauss16", "atrous"]
HOST_FILTERS = ["RT", "RTLightmap"]


def need(module, what):
    try:
        return __import__(module)
    except ImportError:
        sys.exit(f"oidn_ceiling.py: Python module '{module}' ({what}) is missing from this interpreter; "
                 "run scripts/install-deps.sh --oidn and use .venv/bin/python")


def read_y(path, exr, np):
    with exr.File(path) as f:
        return np.asarray(f.channels()["Y"].pixels, dtype=np.float32)


def write_y(path, y, exr, np):
    header = {"compression": exr.ZIP_COMPRESSION, "type": exr.scanlineimage}
    with exr.File(header, {"Y": np.ascontiguousarray(y, dtype=np.float32)}) as f:
        f.write(path)


def oidn_filter(oidn, np, y, kind):
    """OIDN on the Y image given as R = G = B; returns (filtered Y, host ms median of 5)."""
    rgb = np.repeat(y[:, :, None], 3, axis=2).astype(np.float32)
    kw = {"hdr": True} if kind == "RT" else {}
    oidn.denoise(rgb, filter_type=kind, **kw)  # warm-up (the filter's set-up)
    times, out = [], None
    for _ in range(5):
        t0 = time.perf_counter()
        out = oidn.denoise(rgb, filter_type=kind, **kw)
        times.append(1e3 * (time.perf_counter() - t0))
    return out.mean(axis=2), statistics.median(times)


def luminaires(names):
    files = sorted(f for f in os.listdir(LUMDIR) if f.lower().endswith(".ldt"))
    if not names:
        return files
    picked = []
    for n in names.split(","):
        hit = [f for f in files if f.upper().startswith(n.upper())]
        if not hit:
            sys.exit(f"oidn_ceiling.py: --luminaires: no file in {LUMDIR} starts with '{n}'")
        picked.append(hit[0])
    return picked


def run_scene(a, path, h, rot, tmp, oidn, exr, np):
    """Every N, seed and filter of one scene: NMSE and times."""
    ref = os.path.join(tmp, "ref.exr")
    render(path, h, rot, "reference:tol=1e-4", a.res, ref, 1)
    rows = []
    for n in a.ns:
        for seed in range(1, a.seeds + 1):
            row = {"n": n, "seed": seed, "nmse": {}, "device_ms": {}, "host_ms": {}}
            for f in DEVICE_FILTERS:
                out = os.path.join(tmp, f"{f}.exr")
                doc = render(path, h, rot, f"{MC},n={n},seed={seed},denoise={f}", a.res, out, 5)
                row["nmse"][f] = nmse(ref, out)
                row["device_ms"][f] = doc["time_ms"]["median"]
            y = read_y(os.path.join(tmp, "none.exr"), exr, np)
            for kind in HOST_FILTERS:
                fy, ms = oidn_filter(oidn, np, y, kind)
                out = os.path.join(tmp, f"oidn-{kind}.exr")
                write_y(out, fy, exr, np)
                row["nmse"][f"oidn-{kind}"] = nmse(ref, out)
                row["host_ms"][f"oidn-{kind}"] = ms
            rows.append(row)
    return rows


def gmean(xs):
    return math.exp(sum(math.log(max(x, 1e-300)) for x in xs) / len(xs))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--res", type=int, default=512)
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--ns", default="1,2,4")
    ap.add_argument("--luminaires", default="")
    ap.add_argument("--scenes", default="0.1:pi/2,1.1:3pi/4")
    a = ap.parse_args()
    a.ns = [int(x) for x in a.ns.split(",")]
    oidn, exr, np = need("pyoidn", "Open Image Denoise"), need("OpenEXR", "EXR files"), need("numpy", "arrays")
    tmp = tempfile.mkdtemp(prefix="oidn")
    scenes = []
    for lum in luminaires(a.luminaires):
        for h, rot in parse_scenes(a.scenes, "oidn_ceiling.py"):
            rows = run_scene(a, os.path.join(LUMDIR, lum), h, rot, tmp, oidn, exr, np)
            scenes.append({"luminaire": lum, "height": h, "rotation": rot, "rows": rows})
            write_json(a.out, {"partial": True, "res": a.res, "mc": MC, "scenes": scenes})
            print(f"{lum} h {h} R {rot} done", file=sys.stderr, flush=True)
    filters = DEVICE_FILTERS + [f"oidn-{k}" for k in HOST_FILTERS]
    summary = {}
    for n in a.ns:
        rs = [r for s in scenes for r in s["rows"] if r["n"] == n]
        summary[n] = {f: gmean([r["nmse"][f] for r in rs]) for f in filters}
        summary[n]["device_ms"] = {f: statistics.median(r["device_ms"][f] for r in rs) for f in DEVICE_FILTERS}
        summary[n]["host_ms"] = {f"oidn-{k}": statistics.median(r["host_ms"][f"oidn-{k}"] for r in rs)
                                 for k in HOST_FILTERS}
    write_json(a.out, {"res": a.res, "seeds": a.seeds, "ns": a.ns, "mc": MC, "scenes": scenes, "summary": summary})
    print(f"NMSE, geometric mean over {len(scenes)} scenes and {a.seeds} seeds, {a.res}^2 ({MC}):\n")
    print("| N | " + " | ".join(filters) + " | device ms (none, gauss16, atrous) | host ms (RT, RTLightmap) |")
    print("|---|" + "---|" * (len(filters) + 2))
    for n in a.ns:
        s = summary[n]
        dev = ", ".join(f"{s['device_ms'][f]:.1f}" for f in DEVICE_FILTERS)
        host = ", ".join(f"{s['host_ms'][f'oidn-{k}']:.0f}" for k in HOST_FILTERS)
        print(f"| {n} | " + " | ".join(f"{s[f]:.3g}" for f in filters) + f" | {dev} | {host} |")


if __name__ == "__main__":
    main()
