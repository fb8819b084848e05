#!/usr/bin/env python3
"""What calling `simulate` from Python costs against the C++ call (the aim: < 2x on a 20 s record).

For each row, the same block, friction and the first 20 s of El Centro (RSN 175, 140) scaled to
a PGA: the least thread CPU time of `freestand.simulate` over the repeats (the arguments'
type checks, the samples copied in, the summary as a dict and, with series, the arrays out),
against the least of the bare C++ calls (api::simulate of the request: model, excitation and
run) that `_simulate_cpu_s` times inside the module. Run with the module on PYTHONPATH:

    PYTHONPATH=build/default/python python3 bench/python_simulate.py [REPEATS]
"""
import pathlib
import sys
import time

import numpy as np

import freestand
from freestand import _freestand as _fs

ROOT = pathlib.Path(__file__).resolve().parents[1]
REPEATS = int(sys.argv[1]) if len(sys.argv) > 1 else 200

ROWS = [  # label, block, mu, PGA (g)
    ("rest 0.1 g", {"b": 0.2, "h": 0.5, "m": 100}, 0.6, 0.1),
    ("slide 0.5 g", {"b": 0.2, "h": 0.5, "m": 100}, 0.2, 0.5),
    ("rock 0.5 g", {"b": 0.2, "h": 0.5, "m": 100}, 0.6, 0.5),
    ("overturn 0.9 g", {"b": 0.2, "h": 0.5, "m": 100}, 0.6, 0.9),
]


def least_cpu_s(call, repeats):
    best = float("inf")
    for _ in range(repeats):
        t0 = time.thread_time()
        call()
        best = min(best, time.thread_time() - t0)
    return best


def main():
    rec = freestand.read_record(ROOT / "tests/data/RSN175_IMPVALL.H_H-E12140.AT2")
    n = int(round(20.0 / rec.dt_s)) + 1
    accel = np.ascontiguousarray(rec.accel_mps2[:n])
    pga_mps2 = np.max(np.abs(accel))
    print(f"freestand {freestand.__version__}: simulate from Python against the C++ call, "
          f"{n} samples ({(n - 1) * rec.dt_s:g} s), least thread CPU time of {REPEATS} calls")
    print(f"{'row':<18} {'series':<7} {'C++ (ms)':>9} {'Python (ms)':>12} {'ratio':>6} "
          f"{'peak slide (m)':>15} {'theta/alpha':>12} overturned")
    for label, block, mu, pga_g in ROWS:
        scale = pga_g * freestand.g_mps2 / pga_mps2
        for series in (False, True):
            box = freestand._box(block, None, None)
            cpp_s = _fs._simulate_cpu_s(box, mu, accel, rec.dt_s, scale, series, REPEATS)
            result = {}

            def call():
                result.update(freestand.simulate(block, accel, rec.dt_s, mu=mu, scale=scale,
                                                 series=series))

            py_s = least_cpu_s(call, REPEATS)
            print(f"{label:<18} {str(series):<7} {1e3 * cpp_s:>9.4f} {1e3 * py_s:>12.4f} "
                  f"{py_s / cpp_s:>6.2f} {result['slide_max_m']:>15.6g} "
                  f"{result['rock_max_over_alpha']:>12.4g} {result['overturned']}")


if __name__ == "__main__":
    main()
