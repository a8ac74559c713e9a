#!/usr/bin/env python3
"""The paper's Table 1 rows and the filters' equal-time verdicts on one device,
in one command (docs/mc-baselines.md, "Filters at equal time").

    python3 experiments/mc-baselines/gpu_table1.py OUT_DIR [--device N]

1. Table 1: point, cubature, cubature + LTC (the specular scene's `ltc`; its
   time and the sum with the diffuse cubature's), the paper's MC 8 (`paper=1`)
   and MC 8 + DN 2 x 16 (`denoise=gauss16,gauss_radius=16`: the paper's
   16-pixel radius, sigma 8) at 1440^2 and 2880^2, the squares with the pixels
   of 1920 x 1080 and 3840 x 2160; MIREL h 1.1 R 3pi/4; the median of REPS
   launches each (lumibench render --json: OpenCL profiling events).
2. The filters' verdicts: experiments/mc-baselines/strong-gauss-subpixel.json
   and strong-atrous-subpixel.json (MC below one sample per pixel where N = 1
   is slower than the method), shard SHARD of the 42 scenes (default 1/7: 6
   scenes), through lumibench run, tallied by filter_verdicts.py.

Writes OUT_DIR/table1.json (device, driver, commit, every time) and
OUT_DIR/verdicts-{gauss,atrous}.json, each atomically. On a lent H100 the whole
run is meant to take under 8 minutes. Environment: TABLE1_RES (default
"1440,2880"), TABLE1_REPS (default 20), TABLE1_SHARD (default 1/7; "0" skips
part 2), for a reduced run on a CPU device.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import filter_verdicts  # noqa: E402
import lbrun  # noqa: E402

ROWS = [
    ("point", "point", "diffuse"),
    ("cubature", "cubature", "diffuse"),
    ("cubature + LTC (ltc, specular scene)", "ltc", "specular"),
    ("MC 8", "mc:n=8,paper=1", "diffuse"),
    ("MC 8 + DN 2x16", "mc:n=8,paper=1,denoise=gauss16,gauss_radius=16", "diffuse"),
]


def env_int_list(name, default):
    text = os.environ.get(name, default)
    try:
        vals = [int(x) for x in text.split(",")]
    except ValueError:
        sys.exit(f"gpu_table1.py: {name}={text!r}: expected integers separated by commas, e.g. {default}")
    if not vals or any(v < 1 or v > 16384 for v in vals):
        sys.exit(f"gpu_table1.py: {name}={text!r}: each resolution 1 .. 16384")
    return vals


def render(args, spec, scene, res, reps, out):
    lum = os.path.join(lbrun.ZUMTOBEL, "MIREL_42925637.LDT")
    cmd = [lbrun.BIN, "render", "--luminaire", lum, "--method", spec, "--scene", scene, "--height", "1.1",
           "--rotation", "3pi/4", "--res", str(res), "--reps", str(reps), "--out", out, "--json", "--no-cache"]
    if args.device is not None:
        cmd += ["--device", str(args.device)]
    r = subprocess.run(cmd, check=True, capture_output=True, text=True)
    return json.loads(r.stdout)


def table1(args, out_dir):
    resolutions = env_int_list("TABLE1_RES", "1440,2880")
    reps = env_int_list("TABLE1_REPS", "20")[0]
    rows, context = [], {}
    with tempfile.TemporaryDirectory(dir=out_dir) as tmp:
        for res in resolutions:
            times = {}
            for label, spec, scene in ROWS:
                rec = render(args, spec, scene, res, reps, os.path.join(tmp, "img.exr"))
                context = {k: rec.get(k) for k in ("device", "driver")}
                times[label] = rec["time_ms"]["median"]
                rows.append({"row": label, "spec": spec, "scene": scene, "res": res, "pixels": res * res,
                             "time_ms": rec["time_ms"], "stage_ms": rec.get("stats", {}).get("stage_ms")})
                print(f"{res}^2 {label:<40} {times[label]:9.3f} ms", flush=True)
            rows.append({"row": "cubature + LTC (sum: diffuse cubature + specular ltc)", "res": res,
                         "pixels": res * res,
                         "time_ms": {"median": times["cubature"] + times["cubature + LTC (ltc, specular scene)"]}})
    commit = subprocess.run(["git", "-C", HERE, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    lbrun.write_json(os.path.join(out_dir, "table1.json"),
                     {"context": dict(context, commit=commit, date=time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())),
                      "scene": "MIREL_42925637.LDT h 1.1 R 3pi/4", "reps": reps, "rows": rows})


def verdicts(args, out_dir):
    shard = os.environ.get("TABLE1_SHARD", "1/7")
    if shard == "0":
        return
    for name in ("gauss", "atrous"):
        run_dir = os.path.join(out_dir, f"strong-{name}")
        cmd = [lbrun.BIN, "run", os.path.join(HERE, f"strong-{name}-subpixel.json"), "--out", run_dir, "--shard", shard,
               "--luminaires", lbrun.ZUMTOBEL, "--no-report", "--quiet"]
        if args.device is not None:
            cmd += ["--device", str(args.device)]
        subprocess.run(cmd, check=True)
        rows = filter_verdicts.tally(filter_verdicts.load(os.path.join(run_dir, "results.json")))
        for label, r in rows.items():
            print(f"strong+{name} vs {label}: pairs {r['pairs']}, off-time {r['off_time']}, "
                  f"NMSE {filter_verdicts.wtl(r['nmse'])}, FLIP {filter_verdicts.wtl(r['flip'])}", flush=True)
        lbrun.write_json(os.path.join(out_dir, f"verdicts-{name}.json"),
                         {"shard": shard, "verdicts": {k: {kk: vv for kk, vv in v.items() if kk != "log_nmse"}
                                                       for k, v in rows.items()}})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", help="output directory (created)")
    ap.add_argument("--device", type=int, help="OpenCL device index (lumibench devices)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    t0 = time.time()
    table1(a, a.out)
    verdicts(a, a.out)
    print(f"gpu_table1.py: {time.time() - t0:.0f} s", flush=True)


if __name__ == "__main__":
    main()
