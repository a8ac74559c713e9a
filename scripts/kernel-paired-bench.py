#!/usr/bin/env python3
"""Paired timing of two kernel trees with one build: per round, every spec is
rendered once with each tree (LUMIBENCH_KERNEL_DIR), the order of the trees
alternating from round to round, so that both see the same machine load;
prints per spec the median kernel time (render --json time_ms.median: OpenCL
profiling events, median of its launches after a warm-up) of each tree and
the ratio of the medians (B / A) with its range over the rounds.
    scripts/kernel-paired-bench.py A_KERNELS B_KERNELS [--rounds N] [--res N] [SPEC ...]
LB=path picks the program (default build/lumibench). Each tree compiles into
its own POCL_CACHE_DIR (under /tmp), so compile time stays out of it."""
import argparse, hashlib, json, os, statistics, subprocess, sys

DEFAULT = ['cubature', 'cubature:triangulation=delaunay,dynamic=cp+barycentre',
           'cubature:triangulation=delaunay,dynamic=cp+np+mrp+barycentre',
           'cubature:triangulation=delaunay,static=1', 'cubature:triangulation=delaunay,static=3',
           'cubature:lanes=1', 'cubature:horizon_eps=0.3,blend_dist=2']


def render(lb, kdir, spec, a):
    env = dict(os.environ, LUMIBENCH_KERNEL_DIR=kdir,
               POCL_CACHE_DIR='/tmp/lb-pocl-' + hashlib.md5(os.path.abspath(kdir).encode()).hexdigest()[:12])
    cmd = [lb, 'render', '--luminaire', a.luminaire, '--method', spec, '--height', a.height, '--rotation',
           a.rotation, '--res', str(a.res), '--out', '/tmp/lb-paired-bench.exr', '--json']
    out = subprocess.run(cmd, env=env, check=True, capture_output=True, text=True).stdout
    return json.loads(out)['time_ms']['median']


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('a')
    ap.add_argument('b')
    ap.add_argument('specs', nargs='*')
    ap.add_argument('--rounds', type=int, default=5)
    ap.add_argument('--res', type=int, default=512)
    ap.add_argument('--luminaire', default='luminaires/batwing.ldt')
    ap.add_argument('--height', default='1')
    ap.add_argument('--rotation', default='3pi/4')
    a = ap.parse_intermixed_args()
    lb = os.environ.get('LB', 'build/lumibench')
    specs = a.specs or DEFAULT
    t = {(s, k): [] for s in specs for k in 'ab'}
    for s in specs:  # warm-up: compile both trees' programs
        render(lb, a.a, s, a), render(lb, a.b, s, a)
    for r in range(a.rounds):
        for s in specs:
            for k in ('ab' if r % 2 == 0 else 'ba'):
                t[(s, k)].append(render(lb, getattr(a, k), s, a))
        print(f'round {r + 1} of {a.rounds} done', file=sys.stderr)
    print(f'{"spec":70s} {"A ms":>8s} {"B ms":>8s} {"B/A":>6s}  per-round B/A range')
    for s in specs:
        ma, mb = statistics.median(t[(s, 'a')]), statistics.median(t[(s, 'b')])
        per = [y / x for x, y in zip(t[(s, 'a')], t[(s, 'b')])]
        print(f'{s:70s} {ma:8.3f} {mb:8.3f} {mb / ma:6.3f}  {min(per):.3f} .. {max(per):.3f}')


if __name__ == '__main__':
    main()
