#!/usr/bin/env python3
"""CPU time of `vbim decode` writing every picture as a file, per PNG level and for raw RGBA.

Per batch and per output (PNG at each --png-level given, and --format rgba, which is the decode and
the CSC with a plain write), the median over RUNS decodes of the command's CPU time (user + system,
from the kernel's accounting of the child: os.wait4) and of that time per picture. Each decode
writes a directory of its own under WORKDIR, none removed while the batches run (on ext4 a file
created just after many deletions costs more: bench/player/image_share.sh says why).

    bench/streams/decode_files_speed.py VBIM [--batches B] [--runs N] [--levels 0,1,6] [--stream PATH]
        [--workdir DIR]

A level 'default' passes no --png-level (the command's default; the only choice for a vbim from
before the option, 2026-12-06).

Without --stream, a 512x512 Technique A stream of 60 pictures is authored first (`vbim author
--procedural`, which needs vbim-full beside VBIM); its lightmap pictures are decoded.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def cpu_of(cmd):
    """Runs cmd (its output dropped); returns (exit status, CPU seconds: user + system)."""
    with open(os.devnull, "wb") as null:
        proc = subprocess.Popen(cmd, stdout=null, stderr=subprocess.PIPE)
        _, status, usage = os.wait4(proc.pid, 0)
        err = proc.stderr.read().decode(errors="replace")
        proc.stderr.close()
        proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        sys.exit(f"decode_files_speed.py: {' '.join(cmd)} failed (exit {proc.returncode}): {err.strip()}")
    return usage.ru_utime + usage.ru_stime


def pictures_in(directory):
    return sum(1 for name in os.listdir(directory) if name.startswith("frame_"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("vbim")
    ap.add_argument("--batches", type=int, default=3)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--levels", default="0,1,6")
    ap.add_argument("--stream")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    levels = a.levels.split(",")
    if any(x != "default" and (not x.isdigit() or int(x) > 9) for x in levels):
        sys.exit(f"decode_files_speed.py: --levels '{a.levels}': expected 0 to 9 or 'default', separated by commas")
    if a.batches < 1 or a.runs < 1:
        sys.exit("decode_files_speed.py: --batches and --runs: expected at least 1")
    work = a.workdir or tempfile.mkdtemp(prefix="vbim-decode-files.")
    os.makedirs(work, exist_ok=True)
    try:
        stream = a.stream
        if not stream:
            stream = os.path.join(work, "ta512.vbim")
            if not os.path.exists(stream):
                subprocess.run([a.vbim, "author", "--procedural", "--size", "512", "--sky-width", "256",
                                "--frame-count", "60", "--fps", "1", "--out", stream],
                               check=True, stdout=subprocess.DEVNULL)
        outputs = [("png, default" if level == "default" else f"png level {level}",
                    [] if level == "default" else ["--png-level", level]) for level in levels]
        outputs.append(("rgba (raw)", ["--format", "rgba"]))
        load = os.getloadavg()[0]
        print(f"vbim decode of {stream}, {a.runs} runs a batch; "
              f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {os.cpu_count()} CPUs, load average {load:.2f}")
        n = 0
        for batch in range(1, a.batches + 1):
            for label, args in outputs:
                cpus = []
                pictures = 0
                for _ in range(a.runs):
                    n += 1
                    out = os.path.join(work, f"decode.{os.getpid()}.{n}")
                    cpus.append(cpu_of([a.vbim, "decode", stream, "--out", out] + args))
                    pictures = pictures_in(out)
                cpu = statistics.median(cpus)
                print(f"batch {batch}, {label:12}: {cpu:.3f} s CPU for {pictures} pictures, "
                      f"{1000 * cpu / max(pictures, 1):.2f} ms a picture")
    finally:
        if not a.workdir:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
