#!/usr/bin/python3
"""Do the fits' standard errors cover the truth?

Reads the -parameters.csv that bench/diagnosis_success.sh writes beside its rates: for each
synthetic data set, every fitted parameter of the hidden model (the baseline for none) with the
generator's true value and the reported standard error. If the errors were right, the
standardised error z = (fitted - true) / standard error would be roughly normal: |z| < 1 in
about 68 % of the fits and |z| < 2 in about 95 %, median |z| 0.67.

    /usr/bin/python3 bench/parameter_coverage.py ROWS.csv [ROWS.csv ...]

Prints, per parameter (and per way of making the standard errors, where the rows have a
method column), the fits with a standard error, the fraction within 1 and 2 standard
errors, the median |z| and the median relative error |fitted - true| / true of those fits;
fits without a standard error (mechanism switched off, curvature not positive definite, value
on a search bound) are counted apart.
"""
import csv
import statistics
import sys


def main(paths):
    rows = [r for p in paths for r in csv.DictReader(open(p))]
    if not rows:
        sys.exit("parameter_coverage.py: no rows in " + ", ".join(paths))
    # Rows of bench/calibration_coverage.sh say how their standard errors were made.
    methods = list(dict.fromkeys(r.get("method") or "as reported" for r in rows))
    for method in methods:
        if len(methods) > 1:
            print("standard errors from the %s" % method)
        table([r for r in rows if (r.get("method") or "as reported") == method])


def table(rows):
    by_parameter = {}
    for r in rows:
        by_parameter.setdefault(r["parameter"], []).append(r)
    print("%-18s %5s %8s %8s %9s %10s %14s" % ("parameter", "fits", "|z|<1", "|z|<2", "median|z|", "median rel", "no std. error"))
    everything = []
    for name, mine in by_parameter.items():
        z, relative, missing = [], [], 0
        for r in mine:
            truth, fitted = float(r["truth"]), float(r["fitted"])
            if not r["standard_error"] or float(r["standard_error"]) <= 0.0:
                missing += 1
                continue
            z.append((fitted - truth) / float(r["standard_error"]))
            if truth != 0.0:
                relative.append(abs(fitted - truth) / abs(truth))
        everything += z
        print_row(name, z, relative, missing)
    print_row("all", everything, [], sum(1 for r in rows if not r["standard_error"]))


def print_row(name, z, relative, missing):
    if not z:
        print("%-18s %5d %8s %8s %9s %10s %14d" % (name, 0, "-", "-", "-", "-", missing))
        return
    within = lambda k: sum(abs(v) < k for v in z) / len(z)
    print("%-18s %5d %7.0f%% %7.0f%% %9.2f %10s %14d" % (
        name, len(z), 100 * within(1), 100 * within(2), statistics.median(abs(v) for v in z),
        "%.3f" % statistics.median(relative) if relative else "-", missing))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
