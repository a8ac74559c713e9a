#!/usr/bin/env python3
"""Mean HDR-FLIP co-process of lumibench (host/metrics/flip.h).

Started once per lumibench process, on the first FLIP request, with the
Python of the project's .venv (or $LUMIBENCH_FLIP_PYTHON). It first writes one
line on stdout:

    {"ready": "flip-evaluator 1.7"}          the package imports
    {"unavailable": "ModuleNotFoundError: ..."}   it does not (then it exits)

then answers one JSON line per request line read on stdin:

    {"reference": PATH, "test": PATH, "width": W, "height": H}
 -> {"flip": MEAN}  (null when every test pixel is non-finite)
 or {"error": "what went wrong"}

PATH holds W*H little-endian float32 values, row by row (illuminance in lux).
The mean is NVIDIA's flip_evaluator.evaluate(reference, test, "HDR") with its
HDR defaults, the Y image given as R = G = B. FLIP needs finite, non-negative
HDR input, so a non-finite test pixel takes the reference's value (no error
there) and is left out of the mean, like every other metric leaves it out;
negative values (which only an approximation can produce) are clamped to 0.
Anything else the package prints goes to stderr, never into the answers.
"""
import json
import math
import os
import sys


def answer(out, obj):
    out.write(json.dumps(obj) + "\n")
    out.flush()


def mean_flip(np, flip_evaluator, req):
    w, h = int(req["width"]), int(req["height"])
    if w < 1 or h < 1:
        raise ValueError("width and height must be >= 1, found {}x{}".format(w, h))
    imgs = []
    for key in ("reference", "test"):
        a = np.fromfile(req[key], dtype="<f4")
        if a.size != w * h:
            raise ValueError("{} {} holds {} values, expected {}x{} = {}".format(key, req[key], a.size, w, h, w * h))
        imgs.append(a.astype(np.float32).reshape(h, w))
    ref, test = imgs
    if not np.isfinite(ref).all():
        raise ValueError("the reference has non-finite pixels")
    keep = np.isfinite(test)
    if not keep.any():
        return None
    test = np.where(keep, test, ref)
    rgb = [np.repeat(np.maximum(x, 0.0)[:, :, None], 3, axis=2).astype(np.float32) for x in (ref, test)]
    # a fresh parameters dict each call: the default argument is one shared dict
    err, _, _ = flip_evaluator.evaluate(rgb[0], rgb[1], "HDR", applyMagma=False, parameters={})
    err = np.asarray(err, dtype=np.float64).reshape(h, w)
    return float(err[keep].mean())


def main():
    out = os.fdopen(os.dup(1), "w")  # the answers
    os.dup2(2, 1)                    # whatever else writes to stdout lands on stderr
    sys.stdout = sys.stderr
    # flip-evaluator runs on OpenMP (libgomp), whose idle threads spin by
    # default: on a machine with few cores they took the CPU from the OpenCL
    # kernels being timed next, and each FLIP of a 32 x 32 image took 0.3 s
    # instead of 7 ms on 2 busy cores. Passive waiting, unless the user chose
    # a policy; libgomp reads it when the package's library loads, below.
    os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    try:
        import numpy as np
        import flip_evaluator
        from importlib.metadata import version
        ready = "flip-evaluator " + version("flip-evaluator")
    except Exception as e:  # noqa: BLE001 -- any import failure means "not available"
        answer(out, {"unavailable": "{}: {} (Python {})".format(type(e).__name__, e, sys.executable)})
        return 0
    answer(out, {"ready": ready})
    for line in sys.stdin:
        if not line.strip():
            continue
        try:
            v = mean_flip(np, flip_evaluator, json.loads(line))
            answer(out, {"flip": v if v is None or math.isfinite(v) else None})
        except (Exception, SystemExit) as e:  # noqa: BLE001 -- the caller reports it
            answer(out, {"error": "{}: {}".format(type(e).__name__, e)})
    return 0


if __name__ == "__main__":
    sys.exit(main())
