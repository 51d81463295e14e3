#!/usr/bin/python3
"""The most an ensemble could save by stopping lanes that are at rest for good.

A lane standing at rest cannot start to rock or slide while the table acceleration stays below
a margin c of its onset, c g min(tan alpha, mu), mu the lowest friction coefficient of its law
(the spring contacts add dynamic overshoot, hence c < 1). From the first step after which the
rest of a lane's scaled record stays below that bound, the lane could stop without changing its
outcome. Counting every lane as at rest from that step on (an upper bound: a lane still
rocking there would run on), this prints the share of the ensemble's lane-steps such a stop
could save, for several margins.

  bench/rest_tail.py RESULT.h5 RECORD.AT2 --time-scale 0.57735 [--margins 0.5,0.8,1.0]

RESULT.h5 is a planar one-record ensemble's result file (caskdem ensemble) with a constant,
static-kinetic or exponential friction law; the record is a PEER NGA .AT2 file in g, its time
compressed by --time-scale (1/sqrt(N) for a 1/N model).
"""
import argparse
import re

import h5py
import numpy as np

STANDARD_GRAVITY = 9.80665  # m/s^2


def read_at2(path):
    lines = open(path).read().splitlines()
    header = lines[3].upper()
    dt = float(re.search(r"DT=\s*([0-9.Ee+-]+)", header).group(1))
    values = np.array([float(x) for line in lines[4:] for x in line.split()])
    return dt, values * STANDARD_GRAVITY


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("result")
    ap.add_argument("record")
    ap.add_argument("--time-scale", type=float, required=True,
                    help="factor on the record's time: 1 at full scale, 1/sqrt(N) for a 1/N model")
    ap.add_argument("--margins", default="0.5,0.8,1.0")
    args = ap.parse_args()

    with h5py.File(args.result, "r") as f:
        if int(f.attrs["dimensions"]) != 2:
            raise SystemExit(f"{args.result}: a planar ensemble expected (its tilt about one axis)")
        if 'law = "table"' in str(f.attrs["ensemble_toml"]):
            raise SystemExit(f"{args.result}: a tabulated friction law: its lowest coefficient is not in the file")
        if f["motions/pga"].shape[0] != 1:
            raise SystemExit(f"{args.result}: one motion expected, found {f['motions/pga'].shape[0]}")
        alpha = float(f.attrs["stability_angle_rad"])
        r = f["realisations"]
        scale = r["scale_factor"][:]
        end = r["end_time"][:]
        mu = np.minimum(r["friction_static"][:], r["friction_kinetic"][:])
        stripe = r["stripe"][:]
    dt, acceleration = read_at2(args.record)
    time = np.arange(acceleration.size) * dt * args.time_scale
    # The runs' part of the record (the longest run ends with it), and its largest |a| from
    # each sample to the end.
    keep = time <= end.max() + dt * args.time_scale
    time, acceleration = time[keep], acceleration[keep]
    tail_max = np.maximum.accumulate(np.abs(acceleration)[::-1])[::-1]
    onset = STANDARD_GRAVITY * np.minimum(np.tan(alpha), mu)

    print(f"{end.size} realisations, {end.sum():.0f} realisation-seconds, alpha {alpha:.4f} rad")
    for margin in [float(m) for m in args.margins.split(",")]:
        # First sample after which the scaled record stays below the margin (binary search on
        # the non-increasing tail maximum), then the lane-time past it.
        bound = margin * onset / scale
        first_quiet = np.searchsorted(-tail_max, -bound, side="right")
        quiet_from = np.where(first_quiet < time.size, time[np.minimum(first_quiet, time.size - 1)], np.inf)
        saved = np.maximum(0.0, end - quiet_from)
        by_stripe = " ".join(f"{saved[stripe == s].sum() / end[stripe == s].sum():.2f}" for s in np.unique(stripe))
        print(f"margin {margin:.2f}: at most {saved.sum() / end.sum():.3f} of the lane-time; by stripe {by_stripe}")


if __name__ == "__main__":
    main()
