"""The time one lb.render call takes beyond the kernel's profiled device time
(docs/python.md, "Overhead of a call").

For each resolution: one call to build the program, then CALLS calls of
lb.render(..., reps=REPS), each timed with time.perf_counter. A call launches
the kernel 1 + REPS times (one warm-up, REPS timed; `info['time_ms']['samples']`
has the timed ones, the warm-up is counted at their median). Per call:

  kernel  = the launches' profiled device time
  beyond  = wall - kernel: program lookup, buffers, the table's upload, the
            image's readback and conversion, the binding
  binding = wall - info['wall_ms']: the Python shell alone (arguments, GIL,
            the numpy array, the info dict)
  host_cpu = the calling thread's CPU time (time.thread_time): the host work
            of the call, which on a loaded machine takes a fraction of the
            wall time it spends (the kernels run on PoCL's own threads, and
            the calling thread sleeps while it waits for them)

Printed: the medians over the calls and beyond / kernel in per cent.

    PYTHONPATH=build/python .venv/bin/python python/tools/overhead.py [--calls 15] [--reps 5] [--spec cubature]
"""

import argparse
import json
import os
import statistics
import time

import lumibench as lb


def measure(lum, res, spec, calls, reps):
    scene = lb.Scene(height=1.0, rotation="3pi/4", res=res)
    lb.render(lum, scene, spec, reps=reps)  # builds the program
    rows = []
    for _ in range(calls):
        c0, t0 = time.thread_time(), time.perf_counter()
        img, info = lb.render(lum, scene, spec, reps=reps)
        wall, cpu = (time.perf_counter() - t0) * 1e3, (time.thread_time() - c0) * 1e3
        samples = info["time_ms"]["samples"]
        kernel = sum(samples) + statistics.median(samples)
        rows.append((wall, kernel, wall - kernel, wall - info["wall_ms"], cpu))
    wall, kernel, beyond, binding, cpu = (statistics.median(c) for c in zip(*rows))
    return {"res": res, "spec": spec, "reps": reps, "calls": calls, "wall_ms": round(wall, 3),
            "kernel_ms": round(kernel, 3), "beyond_ms": round(beyond, 3), "beyond_pct": round(100 * beyond / kernel, 2),
            "binding_ms": round(binding, 3), "binding_pct": round(100 * binding / kernel, 3),
            "host_cpu_ms": round(cpu, 3), "host_cpu_pct": round(100 * cpu / kernel, 2), "device": info["device"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--calls", type=int, default=15)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--spec", default="cubature")
    ap.add_argument("--res", type=int, nargs="+", default=[64, 512])
    a = ap.parse_args()
    lum = lb.Luminaire.load(os.path.join(os.path.dirname(__file__), "..", "..", "luminaires", "batwing.ldt"))
    for res in a.res:
        r = measure(lum, res, a.spec, a.calls, a.reps)
        r["load"] = os.getloadavg()[0]
        print(json.dumps(r))


if __name__ == "__main__":
    main()
