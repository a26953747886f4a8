#!/usr/bin/env python3
"""How often the three IDCTs (ipu.idct, docs/timing/ipu.md#idct) differ on real streams.

Decodes each stream with `vbim decode --format yuv --idct KIND` for every kind and prints, per pair
of kinds, the range over the pictures of the share of samples (Y, Cb, Cr) that differ, and the
largest difference. With Debian's `mpeg2dec` installed, also compares each kind with
`mpeg2dec -c` (libmpeg2's C decoder) on the first video stream (0xE0) of a program stream.

    scripts/idct-differences.py [--vbim build/cli/vbim] [STREAM ...]

Default streams: streams/samples/day_clear.vbim and day_weather.vbim.
"""
import argparse
import itertools
import os
import shutil
import subprocess
import sys
import tempfile

KINDS = ["pcsx2", "libmpeg2", "exact"]
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def decode(vbim, stream, kind, out):
    subprocess.run([vbim, "decode", stream, "--out", out, "--format", "yuv", "--idct", kind, "--force"],
                   check=True, stdout=subprocess.DEVNULL)
    return [open(os.path.join(out, f), "rb").read() for f in sorted(os.listdir(out))]


def mpeg2dec_pictures(stream, out, width, height):
    """libmpeg2's C decode of stream 0xE0 as planar Y, Cb, Cr per picture (from its PGM output)."""
    os.makedirs(out)
    subprocess.run(["mpeg2dec", "-c", "-s0xe0", "-o", "pgm", os.path.abspath(stream)], cwd=out, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    pictures = []
    for i in itertools.count():
        path = os.path.join(out, f"{i}.pgm")
        if not os.path.exists(path):
            return pictures
        data = open(path, "rb").read()
        pixels = data[data.index(b"255\n") + 4:]
        luma, chroma = pixels[:width * height], pixels[width * height:]
        half = width // 2
        cb = b"".join(chroma[r * width:r * width + half] for r in range(height // 2))
        cr = b"".join(chroma[r * width + half:(r + 1) * width] for r in range(height // 2))
        pictures.append(luma + cb + cr)


def compare(a, b):
    """Per-picture % of differing samples (min, max) and the largest difference."""
    shares, largest = [], 0
    for x, y in zip(a, b):
        different = sum(1 for p, q in zip(x, y) if p != q)
        shares.append(100.0 * different / len(x))
        largest = max([largest] + [abs(p - q) for p, q in zip(x, y) if p != q])
    return min(shares), max(shares), largest, len(shares)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--vbim", default=os.path.join(ROOT, "build/cli/vbim"))
    parser.add_argument("streams", nargs="*", default=[os.path.join(ROOT, "streams/samples/day_clear.vbim"),
                                                       os.path.join(ROOT, "streams/samples/day_weather.vbim")])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for n, stream in enumerate(args.streams):
            decoded = {k: decode(args.vbim, stream, k, os.path.join(tmp, f"{n}-{k}")) for k in KINDS}
            name = os.path.basename(stream)
            for a, b in itertools.combinations(KINDS, 2):
                lo, hi, largest, count = compare(decoded[a], decoded[b])
                print(f"{name}: {a} vs {b}: {lo:.3f}-{hi:.3f} % of samples differ per picture "
                      f"({count} pictures), largest difference {largest}")
            if shutil.which("mpeg2dec") is None:
                continue
            # The picture size from the planar 4:2:0 size, assuming a square picture as the samples are.
            side = int(round((len(decoded["pcsx2"][0]) / 1.5) ** 0.5))
            reference = mpeg2dec_pictures(stream, os.path.join(tmp, f"{n}-mpeg2dec"), side, side)
            for k in KINDS:
                lo, hi, largest, count = compare(decoded[k], reference)
                print(f"{name}: {k} vs mpeg2dec -c: {lo:.3f}-{hi:.3f} % of samples differ per picture "
                      f"({count} pictures), largest difference {largest}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
