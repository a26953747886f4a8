#!/usr/bin/env python3
"""Runs BM_GopDecode of several builds of bench_ipu_gop_decode in alternation and compares their ratios.

BM_GopDecode already times our decoder against libmpeg2 (YCbCr) and libavcodec + swscale (RGBA)
in interleaved rounds of one process, so its ratios carry less of the shared machine's load than
the CPU times ab_compare.py compares. Runs of the builds (the one before a change, copied aside, and
the one after it) alternate RUNS times; per build and stream, the median and range of each ratio
over its runs are printed: a change that moves the ratios of its build beyond the other's range is
a gain on that load.

    bench/ipu/alternate_gop.py [--runs N] BENCH [BENCH ...]
    bench/ipu/alternate_gop.py --runs 3 /tmp/before build/bench/ipu/bench_ipu_gop_decode
"""
import argparse
import statistics
import sys

from bench_runs import BenchError, case_label, check_runs, run_bench

RATIOS = ["x_libmpeg2_yuv", "x_libav_rgba"]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--filter", default="BM_GopDecode/")
    ap.add_argument("bench", nargs="+")
    args = ap.parse_args()
    check_runs(ap, args.runs)
    values: dict[str, dict[tuple[str, str], list[float]]] = {b: {} for b in args.bench}
    for run in range(args.runs):
        for b in args.bench:
            try:
                benchmarks = run_bench(b, args.filter)
            except BenchError as e:
                print(f"alternate_gop.py: {e}", file=sys.stderr)
                return 1
            for r in benchmarks:
                case = case_label(r["name"])
                for c in RATIOS:
                    if c in r:
                        values[b].setdefault((case, c), []).append(float(r[c]))
        print(f"run {run + 1}/{args.runs} done", file=sys.stderr)
    print(f"Medians over {args.runs} alternated runs (min-max):")
    for b in args.bench:
        print(f"\n{b}")
        if not values[b]:
            print(f"  (the filter {args.filter!r} selects no BM_GopDecode case)")
        for (case, c), v in sorted(values[b].items()):
            print(f"  {case:22s} {c:15s} {statistics.median(v):.3f} ({min(v):.3f}-{max(v):.3f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
