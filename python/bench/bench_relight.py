#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Relighting a 3840x2160 float RGB numpy image: the Python call against the
C++ API (Relighter::apply), on the same pixels, in ns per pixel.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_relight.py \\
        [--cpp build/python/bench_relight_cpp] [--methods band3,rootpoly] \\
        [--threads 1,2] [--runs 7]

The C++ figure comes from bench_relight_cpp (python/bench/bench_relight_cpp.cpp,
built beside the module): Relighter::apply in place on a packed buffer. The
Python figures: Relighter.apply(image, out=image), the same call in place;
Relighter.apply(image, out=buffer), copying block by block into an existing
array; and Relighter.apply(image), which also allocates the result. Each is
the median of --runs, the image reset before each run (not timed).
"""

import argparse
import pathlib
import subprocess
import time

import numpy as np

import bandlight

WIDTH, HEIGHT = 3840, 2160


def pristine():
    # The pixels of bench/ApplyBench.cpp's native benchmarks (and of bench_relight_cpp).
    i = np.arange(WIDTH * HEIGHT * 3, dtype=np.uint64)
    return (((i * np.uint64(2654435761)) % np.uint64(1000)).astype(np.float32)
            * np.float32(0.001)).reshape(HEIGHT, WIDTH, 3)


def checksum(image):
    flat = image.reshape(-1)
    return float(np.sum(flat[::4099].astype(np.float64)))


def median_ns(fn, reset, runs):
    times = []
    for _ in range(runs):
        reset()
        t0 = time.perf_counter_ns()
        fn()
        times.append((time.perf_counter_ns() - t0) / (WIDTH * HEIGHT))
    return sorted(times)[len(times) // 2]


def main():
    default_cpp = pathlib.Path(bandlight.__file__).resolve().parents[1] / "bench_relight_cpp"
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cpp", default=str(default_cpp), help="the bench_relight_cpp program")
    ap.add_argument("--methods", default="bradford,rootpoly,rootpoly3")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--runs", type=int, default=7)
    args = ap.parse_args()

    source = pristine()
    image = source.copy()
    out = np.empty_like(source)
    print(f"{WIDTH}x{HEIGHT} float32 RGB, A -> D65 in ACEScg, median of {args.runs} runs, "
          "ns per pixel")
    print(f"{'method':10} {'threads':>7} {'copy':>6} {'C++ API':>9} {'py in place':>12} "
          f"{'py into out':>12} {'py new array':>13}   (in place / copy)")
    for method in args.methods.split(","):
        # Lit plates, as bench_relight_cpp times them.
        r = bandlight.Relighter("A", "D65", method, plates="lit")
        for threads in (int(t) for t in args.threads.split(",")):
            cpp = subprocess.run([args.cpp, method, str(threads), str(args.runs)],
                                 capture_output=True, text=True, check=True).stdout
            fields = dict(f.split("=", 1) for f in cpp.split()[1:])

            def reset():
                np.copyto(image, source)

            in_place = median_ns(lambda: r.apply(image, out=image, threads=threads), reset,
                                 args.runs)
            same = abs(checksum(image) - float(fields["checksum"])) < 1e-6 * abs(
                float(fields["checksum"])) + 1e-9
            into = median_ns(lambda: r.apply(source, out=out, threads=threads), lambda: None,
                             args.runs)
            new = median_ns(lambda: r.apply(source, threads=threads), lambda: None, args.runs)
            # The physical limit, in the same run: copying the same bytes
            # (numpy's copy is one thread).
            copy = median_ns(lambda: np.copyto(out, source), lambda: None, args.runs)
            print(f"{method:10} {threads:7d} {copy:6.2f} {float(fields['ns_per_pixel']):9.2f} "
                  f"{in_place:12.2f} {into:12.2f} {new:13.2f}   {copy / in_place:.2f}x"
                  + ("" if same else "   (checksums differ!)"))


if __name__ == "__main__":
    main()
