#!/usr/bin/env python3
"""Markdown tables from `lumibench bench --json` documents (README "Performance").

Usage: python3 plots/bench_table.py RUN.json [RUN.json ...]

Prints one line of ratios per run, then the quantity and per-method tables of
the median run (by the cubature / MC 8 ratio). Standard library only.
"""
import json
import statistics
import sys


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: bench_table.py RUN.json [RUN.json ...]")
    runs = []
    for path in sys.argv[1:]:
        try:
            runs.append((path, json.load(open(path))))
        except (OSError, ValueError) as e:
            sys.exit(f"{path}: {e}")
    for path, d in runs:
        print(f"- {path}: MC / naive {d['mc']['ratio']:.1f}, cubature / MC 8 {d['cubature']['ratio']:.2f}, "
              f"equal-time N {d['cubature']['equal_time_n']}, commit {d.get('context', {}).get('commit', '?')[:8]}")
    ratios = [d["cubature"]["ratio"] for _, d in runs]
    med = statistics.median_low(ratios)
    path, d = next(r for r in runs if r[1]["cubature"]["ratio"] == med)
    mc, cub, fit = d["mc"], d["cubature"], d["mc_fit"]
    print(f"\nMedian run: {path}\n")
    print("| quantity | value |\n|---|---|")
    print(f"| device | {d['device']}, {d['driver']} |")
    print(f"| naive MC samples/s (N = {mc['n']}) | {mc['naive_sps']:.2g} |")
    print(f"| fast MC samples/s (N = {mc['n']}) | {mc['fast_sps']:.2g} |")
    print(f"| ratio fast / naive (target >= 10) | **{mc['ratio']:.1f}** ({'met' if mc['ok'] else 'missed'}) |")
    print(f"| cubature / MC 8 time (target <= 1) | **{cub['ratio']:.2f}** ({'met' if cub['ok'] else 'missed'}) |")
    print(f"| cubature's equal-time MC N | {cub['equal_time_n']} (t = {cub['verify_ms']:.2f} ms vs "
          f"{cub['time_ms']:.2f} ms) |")
    print(f"| MC t(N) fit | {fit['t0_ms']:.2f} ms + {fit['ms_per_sample']:.3f} ms per sample |")
    print(f"\n| method ({d['res']}^2) | ms | ns / pixel |\n|---|---|---|")
    for m in d["methods"]:
        print(f"| {m['method']} | {m['time_ms']:.1f} | {m['ns_per_pixel']:.1f} |")


if __name__ == "__main__":
    main()
