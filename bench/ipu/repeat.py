#!/usr/bin/env python3
"""Runs bench_ipu_decode (or bench_ipu_gop_decode, with --bench) several times and summarises its counters over the runs.

One run of the bench already interleaves the decoders it compares and reports medians of
per-round ratios; the spread that is left comes from the host (a virtual machine whose neighbours
come and go), so a figure worth quoting is the median over several runs with its range.

    bench/ipu/repeat.py [--runs N] [--bench build/bench/ipu/bench_ipu_decode] [--filter REGEX]
    bench/ipu/repeat.py --runs N --bench build/bench/ipu/bench_ipu_gop_decode

Prints one Markdown table per benchmark family: median (min-max) over the runs of each counter.
"""
import argparse
import statistics
import sys

from bench_runs import BenchError, case_label, check_runs, run_bench

COUNTERS = {
    "BM_DecodeToRgba": ["ours_fps", "libavcodec_fps", "libmpeg2_fps", "x_libavcodec", "x_libmpeg2", "x_faster",
                        "ours_exact_fps", "x_exact"],
    "BM_SliceParallel": ["speedup_wall", "ceiling", "efficiency", "speedup_cpu", "speedup_wall_nospin", "identical"],
    "BM_GopDecode": ["ours_yuv_fps", "libmpeg2_fps", "x_libmpeg2_yuv", "ours_rgba_fps", "libavcodec_fps", "x_libav_rgba",
                     "l2idct_cost", "all_frames"],
    # One x_<TARGET> (and x_csc_<TARGET>) per narrower Highway target this machine runs: found in the output.
    "BM_GopDecodeTargets": None,
}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=8)
    ap.add_argument("--bench", default="build/bench/ipu/bench_ipu_decode")
    ap.add_argument("--filter", default=".")
    args = ap.parse_args()
    check_runs(ap, args.runs)

    values: dict[str, dict[str, list[float]]] = {}
    for run in range(args.runs):
        try:
            benchmarks = run_bench(args.bench, args.filter)
        except BenchError as e:
            print(f"repeat.py: {e}", file=sys.stderr)
            return 1
        for b in benchmarks:
            case = values.setdefault(b["name"], {})
            for key, v in b.items():
                if isinstance(v, (int, float)):
                    case.setdefault(key, []).append(float(v))
        print(f"run {run + 1}/{args.runs} done", file=sys.stderr)

    def cell(vs: list[float]) -> str:
        fmt = (lambda x: f"{x:,.0f}") if max(vs) >= 100 else (lambda x: f"{x:.2f}")
        return f"{fmt(statistics.median(vs))} ({fmt(min(vs))}-{fmt(max(vs))})"

    print(f"Medians over {args.runs} runs (min-max):")
    for family, listed in COUNTERS.items():
        counters = listed
        cases = [name for name in values if name.startswith(family + "/")]
        if not cases:
            continue
        if counters is None:
            found = {key for name in cases for key in values[name] if key.startswith("x_")}
            counters = sorted(found, key=lambda k: (k.startswith("x_csc_"), k)) + ["same_samples"]
        print(f"\n| {family} | " + " | ".join(counters) + " |")
        print("|---|" + "---:|" * len(counters))
        for name in cases:
            label = case_label(name)
            print(f"| {label} | " + " | ".join(cell(values[name][c]) if c in values[name] else "" for c in counters)
                  + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
