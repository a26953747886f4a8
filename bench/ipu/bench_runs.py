"""What repeat.py, alternate_gop.py and ab_compare.py share: one run of a Google Benchmark binary
with JSON output, and the label of a case without the benchmark's own suffixes.

Imported by those scripts (they run as bench/ipu/NAME.py, so this folder is on sys.path).
"""
import argparse
import json
import subprocess


class BenchError(Exception):
    """A bench binary that could not be started or exited with an error."""


def check_runs(ap: argparse.ArgumentParser, n: int, what: str = "runs") -> None:
    """--runs (or --pairs) N must be at least 1."""
    if n < 1:
        ap.error(f"--{what} must be at least 1")


def run_bench(binary: str, flt: str, min_time: float | None = None) -> list[dict]:
    """The `benchmarks` list of one run of `binary` on the filter; BenchError on failure."""
    cmd = [binary, "--benchmark_format=json", f"--benchmark_filter={flt}"]
    if min_time is not None:
        cmd.append(f"--benchmark_min_time={min_time}")
    try:
        out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        raise BenchError(f"{binary}: {e}") from e
    return json.loads(out)["benchmarks"]


def case_label(name: str) -> str:
    """'BM_GopDecode/interlaced:0/q:2/min_time:0.500' -> 'interlaced:0/q:2'."""
    return "/".join(p for p in name.split("/")[1:] if not p.startswith(("min_time", "real_time")))
