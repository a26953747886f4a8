#!/usr/bin/env python3
"""Compares two builds of one bench binary, run alternately, to measure a change against the one before.

On the shared machine the load moves by tens of percent between minutes, so the two binaries (the
build before a change, copied aside, and the build after it) run in alternation, N pairs, each run
on the same benchmark filter; each pair gives the ratio of the CPU times, before / after (> 1: the
change is faster), and the median and range of those ratios are printed per benchmark.

    bench/ipu/ab_compare.py BEFORE AFTER --filter REGEX [--pairs N] [--min-time S]
    bench/ipu/ab_compare.py /tmp/before build/bench/ipu/bench_ipu_gop_decode \\
        --filter 'BM_GopDecodeOurs/interlaced:0/q:./l2idct:0/rgba:1' --pairs 8
"""
import argparse
import statistics
import sys

from bench_runs import BenchError, check_runs, run_bench


def cpu_times(binary: str, flt: str, min_time: float) -> dict[str, float]:
    return {b["name"]: b["cpu_time"] for b in run_bench(binary, flt, min_time)}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--filter", required=True)
    ap.add_argument("--pairs", type=int, default=8)
    ap.add_argument("--min-time", type=float, default=0.4)
    args = ap.parse_args()
    check_runs(ap, args.pairs, "pairs")
    ratios: dict[str, list[float]] = {}
    for _ in range(args.pairs):
        try:
            before = cpu_times(args.before, args.filter, args.min_time)
            after = cpu_times(args.after, args.filter, args.min_time)
        except BenchError as e:
            print(f"ab_compare: {e}", file=sys.stderr)
            return 1
        if not before or before.keys() != after.keys():
            print(f"ab_compare: the filter {args.filter!r} selects no benchmark, or not the same ones in both "
                  f"binaries ({sorted(before)} against {sorted(after)})", file=sys.stderr)
            return 1
        for name, t in before.items():
            ratios.setdefault(name, []).append(t / after[name])
    print(f"before / after CPU time over {args.pairs} alternated pairs (> 1: after is faster):")
    for name, v in ratios.items():
        print(f"  {name}: median {statistics.median(v):.3f} (range {min(v):.3f}-{max(v):.3f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
