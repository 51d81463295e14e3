#!/usr/bin/python3
"""The time-step verification table of docs/time-step.md from timestep_convergence's rows.

An f_s is acceptable for an ensemble when its fitted answer (each limit state's median and
beta, and the annual frequency) differs from the reference f_s's by less than a quarter of
that answer's 95 % bootstrap band. Stripe probabilities are shown against a quarter of their
Clopper-Pearson interval, for reading: a stripe's count moves by whole realisations. A limit
state whose curve is fitted at the reference step but not at this one is listed (its stripes
still compare); it is left out of the verdict, which the text beside the table discusses.

The verdict is on the answer a user of the shipped ensemble reads, so a run made with more
realisations per stripe than its file ships (timestep_convergence --per-stripe, to measure the
step's bias more finely than the shipped run could) is judged against the shipped run's band.
Under one motion the band comes from resampling each stripe's realisations and narrows as
1/sqrt(per stripe): the run's band is widened by sqrt(per_stripe / shipped_per_stripe). Under
several motions the band comes from resampling the motions, which more draws per stripe do not
remove: the run's own band is kept, narrower than the shipped one's or as wide (a stricter
test). Rows without those columns (older files) take them from the shipped file of the same
name in ensembles/ (its realisations per stripe, its levels and motions), else are judged at
their own band.

usage: bench/timestep_table.py ROWS.csv
"""
import math
import csv
import os
import sys
import tomllib
from collections import defaultdict

ENSEMBLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ensembles")


def shipped_file(ensemble):
    """Per stripe, levels and motions of the shipped ensemble of that name, or None."""
    path = os.path.join(ENSEMBLES, ensemble + ".toml")
    if not os.path.exists(path):
        return None
    with open(path, "rb") as f:
        spec = tomllib.load(f)
    epistemic = any(u.get("kind") == "epistemic" for u in spec.get("uncertain", {}).values())
    outer = int(spec.get("sampling", {}).get("epistemic_points", 1)) if epistemic else 1
    return (int(spec["intensity"]["realisations"]), len(spec["intensity"]["levels"]) * outer, len(spec["motions"]))


def shipped_widening(r):
    """The factor from the run's band to the shipped ensemble's (1 where it cannot be said)."""
    try:
        per_stripe, shipped, motions = int(r["per_stripe"]), int(r["shipped_per_stripe"]), int(r["motions"])
    except (KeyError, TypeError, ValueError):
        file = shipped_file(r["ensemble"])
        if file is None or not r.get("realisations"):
            return 1.0
        shipped, stripes, motions = file  # stripes: levels times epistemic points
        per_stripe = int(r["realisations"]) // stripes
        r["per_stripe"], r["shipped_per_stripe"], r["motions"] = per_stripe, shipped, motions
    return math.sqrt(per_stripe / shipped) if motions == 1 and per_stripe > shipped else 1.0


def ratio(d, band, widening=1.0):
    d, band = float(d), float(band) * widening
    if band != band or d != d:
        return float("nan")
    return abs(d) / (band / 4.0) if band > 0 else (0.0 if d == 0 else float("inf"))


rows = list(csv.DictReader(open(sys.argv[1])))
by = defaultdict(list)
for r in rows:
    by[(r["ensemble"], float(r["safety_factor"]), float(r["stiffness_scale"]), r.get("slider") or "half-step",
        r.get("realisations") or "")].append(r)

print("| ensemble | f_s | step | wall | worst of median, beta, annual frequency (x band/4) | which | worst stripe (x CP/4) | curves not fitted | acceptable |")
print("|---|---|---|---|---|---|---|---|---|")
for (ensemble, fs, k, slider, size), group in by.items():
    worst, which, stripe, unfitted = 0.0, "", 0.0, []
    widening = shipped_widening(group[0])
    for r in group:
        if float(r["d_median_rel"]) != float(r["d_median_rel"]):
            unfitted.append(r["limit_state"])
        for name, d, band in (("median", r["d_median_rel"], r["median_band_rel"]),
                              ("beta", r["d_beta"], r["beta_band"]),
                              ("annual frequency", r["d_frequency_rel"], r["frequency_band_rel"])):
            x = ratio(d, band, widening)
            if x == x and x > worst:
                worst, which = x, f"{name}, {r['limit_state']}"
        x = ratio(r["d_stripe"], r["stripe_band"])
        if x == x:
            stripe = max(stripe, x)
    reference = group[0]["acceptable"] == "reference"
    verdict = "reference" if reference else ("yes" if worst < 1.0 else "no")
    label = ensemble if k == 1.0 else f"{ensemble}, stiffness x{k:g}"
    if slider != "half-step":
        label += f", {slider} slider"
    if widening != 1.0:
        label += f", {int(size):,} realisations against the shipped band"
    elif group[0].get("per_stripe") and int(group[0]["per_stripe"]) > int(group[0]["shipped_per_stripe"]):
        label += f", {int(size):,} realisations against their own band"
    elif size and ensemble.startswith("benchmark") and int(size) > 10000:
        label += f", {int(size):,} realisations"
    print(f"| {label} | {fs:g} | {float(group[0]['time_step_s']):.3g} s | {float(group[0]['wall_s']):.1f} s "
          f"| {worst:.2f} | {which if not reference else '-'} | {stripe:.2f} | {', '.join(unfitted) or '-'} | {verdict} |")
