#!/usr/bin/python3
"""The time-step verification table of docs/time-step.md from timestep_convergence's rows.

An f_s is acceptable for an ensemble when its fitted answer (each limit state's median and
beta, and the annual frequency) differs from the reference f_s's by less than a quarter of
that answer's 95 % bootstrap band. Stripe probabilities are shown against a quarter of their
Clopper-Pearson interval, for reading: a stripe's count moves by whole realisations. A limit
state whose curve is fitted at the reference step but not at this one is listed (its stripes
still compare); it is left out of the verdict, which the text beside the table discusses.

usage: bench/timestep_table.py ROWS.csv
"""
import csv
import sys
from collections import defaultdict


def ratio(d, band):
    d, band = float(d), float(band)
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
    for r in group:
        if float(r["d_median_rel"]) != float(r["d_median_rel"]):
            unfitted.append(r["limit_state"])
        for name, d, band in (("median", r["d_median_rel"], r["median_band_rel"]),
                              ("beta", r["d_beta"], r["beta_band"]),
                              ("annual frequency", r["d_frequency_rel"], r["frequency_band_rel"])):
            x = ratio(d, band)
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
    if size and ensemble.startswith("benchmark") and int(size) > 10000:
        label += f", {int(size):,} realisations"
    print(f"| {label} | {fs:g} | {float(group[0]['time_step_s']):.3g} s | {float(group[0]['wall_s']):.1f} s "
          f"| {worst:.2f} | {which if not reference else '-'} | {stripe:.2f} | {', '.join(unfitted) or '-'} | {verdict} |")
