#!/usr/bin/env python3
"""Checks that two builds of armtrack-cli estimate the same angles, to round-off.

For a change that should move nothing but floating-point round-off (a faster update, a
hand-written Jacobian): simulates a few recordings with the new build, estimates each with both
builds and prints, per case, the largest difference of any angle and any standard deviation,
separately for the start-up second and for the rest. Standard library only.

    tests/support/compare-estimates.py --new build/app/armtrack-cli \\
        --ref /path/to/reference/build/app/armtrack-cli [--work DIR] [--keep]

The start-up second runs the iterated EKF from a covariance of tens of degrees, where round-off
is amplified: there, 1 ulp changes in the IMU readings alone move the reference's angles by
about 5e-9 rad (--ulp-check measures this on the first case). After it, differences of a few
1e-10 rad are round-off; anything that grows with time, or reaches 1e-6, is not.
docs/estimator.md ("Speed") has the figures of the last check.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

# name, simulate options, list of estimate option sets
CASES = [
    ("multi_kinect", ["--trajectory", "multi-joint", "--duration", "60", "--seed", "3"],
     [[], ["--joint-accel-std", "10"], ["--filter", "ukf", "--joint-accel-std", "10"],
      ["--method", "B", "--joint-accel-std", "10"],
      # every method and both filters, with and without the optics
      ["--no-kinect", "--joint-accel-std", "10"],
      ["--no-kinect", "--method", "B", "--joint-accel-std", "10"],
      ["--no-kinect", "--method", "C", "--joint-accel-std", "10"],
      ["--no-kinect", "--filter", "ukf", "--joint-accel-std", "10"],
      ["--method", "C", "--joint-accel-std", "10"],
      ["--filter", "ukf", "--method", "B", "--joint-accel-std", "10"],
      ["--filter", "ukf", "--method", "C", "--joint-accel-std", "10"]]),
    ("multi_webcam", ["--trajectory", "multi-joint", "--duration", "40", "--seed", "4",
                      "--webcam", "--no-kinect"],
     [["--joint-accel-std", "10"], ["--filter", "ukf", "--joint-accel-std", "10"]]),
    ("multi_imus", ["--trajectory", "multi-joint", "--duration", "40", "--seed", "5",
                    "--no-kinect"],
     [[], ["--method", "C", "--joint-accel-std", "10"]]),
    ("reach_420", ["--trajectory", "reaching", "--duration", "40", "--seed", "6",
                   "--peak-rate", "420"],
     [[], ["--joint-accel-std", "10"]]),
]
STARTUP = 1.0  # s after the first estimate counted as start-up


def run(cmd):
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr}")


def read(path):
    with open(path, newline="") as f:
        r = csv.reader(f)
        header = next(r)
        return header, [[float(v) for v in row] for row in r]


def compare(ref_path, new_path):
    """(start-up angle, start-up sd, later angle, later sd) largest absolute differences."""
    h1, a = read(ref_path)
    h2, b = read(new_path)
    if h1 != h2 or len(a) != len(b):
        sys.exit(f"{new_path}: {len(b)} rows {h2}, reference {len(a)} rows {h1}")
    angles = [k for k, n in enumerate(h1) if n.startswith("th")]
    sds = [k for k, n in enumerate(h1) if n.startswith("sd_")]
    other = [k for k, n in enumerate(h1) if k not in angles and k not in sds]
    worst = [0.0] * 4
    t0 = a[0][0] if a else 0.0
    for ra, rb in zip(a, b):
        for k in other:  # time and status must match exactly
            if ra[k] != rb[k] and not (math.isnan(ra[k]) and math.isnan(rb[k])):
                sys.exit(f"{new_path}: {h1[k]} differs at t={ra[0]}: {ra[k]} vs {rb[k]}")
        late = 2 if ra[0] - t0 >= STARTUP else 0
        for k in angles + sds:
            if math.isnan(ra[k]) or math.isnan(rb[k]):
                if math.isnan(ra[k]) != math.isnan(rb[k]):
                    sys.exit(f"{new_path}: NaN in one only at t={ra[0]} {h1[k]}")
                continue
            d = ra[k] - rb[k]
            if k in angles:
                d = math.remainder(d, 2 * math.pi)
            slot = late + (1 if k in sds else 0)
            worst[slot] = max(worst[slot], abs(d))
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--new", required=True, help="armtrack-cli under test")
    ap.add_argument("--ref", required=True, help="armtrack-cli of the reference commit")
    ap.add_argument("--work", help="folder for recordings and outputs (default: a temporary one)")
    ap.add_argument("--ulp-check", action="store_true",
                    help="also estimate the first recording with the reference after moving every "
                         "IMU reading of its first second by 1 ulp: round-off's own reach")
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="compare-estimates-")
    os.makedirs(work, exist_ok=True)
    print(f"{'case':<48} {'start-up angle':>14} {'sd':>9} {'later angle':>12} {'sd':>9}")
    overall = [0.0] * 4
    for name, sim, option_sets in CASES:
        rec = os.path.join(work, name + ".csv")
        if not os.path.exists(rec):
            run([args.new, "simulate", *sim, "--out", rec, "--overwrite"])
        for opts in option_sets:
            tag = name + "".join(o.replace("-", "") for o in opts)
            outs = {}
            for which, cli in (("ref", args.ref), ("new", args.new)):
                outs[which] = os.path.join(work, f"{tag}.{which}.csv")
                run([cli, "estimate", rec, *opts, "--out", outs[which], "--overwrite"])
            w = compare(outs["ref"], outs["new"])
            overall = [max(x, y) for x, y in zip(overall, w)]
            label = f"{name} {' '.join(opts)}"
            print(f"{label:<48} {w[0]:14.1e} {w[1]:9.1e} {w[2]:12.1e} {w[3]:9.1e}")
    print(f"{'largest':<48} {overall[0]:14.1e} {overall[1]:9.1e} {overall[2]:12.1e} "
          f"{overall[3]:9.1e}  (rad)")
    if args.ulp_check:
        name = CASES[0][0]
        src = os.path.join(work, name + ".csv")
        moved = os.path.join(work, name + "_ulp.csv")
        with open(src) as f, open(moved, "w") as out:
            for line in f:
                if line[0] in "#t":
                    out.write(line)
                    continue
                fields = line.rstrip("\n").split(",")
                if float(fields[0]) < STARTUP:
                    for k in range(1, 13):  # the two IMUs' gyroscope and accelerometer columns
                        if fields[k]:
                            fields[k] = repr(math.nextafter(float(fields[k]), math.inf))
                out.write(",".join(fields) + "\n")
        with open(os.path.splitext(src)[0] + ".json") as f, \
                open(os.path.splitext(moved)[0] + ".json", "w") as out:
            out.write(f.read())
        a = os.path.join(work, "ulp.ref.csv")
        b = os.path.join(work, "ulp.moved.csv")
        run([args.ref, "estimate", src, "--out", a, "--overwrite"])
        run([args.ref, "estimate", moved, "--out", b, "--overwrite"])
        w = compare(a, b)
        print(f"{'reference, IMU readings moved 1 ulp':<48} {w[0]:14.1e} {w[1]:9.1e} "
              f"{w[2]:12.1e} {w[3]:9.1e}")
    print(f"files in {work}")


if __name__ == "__main__":
    main()
