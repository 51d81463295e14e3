#!/usr/bin/python3
"""The closed loop's rates as Markdown, from the rows bench/closed_loop.sh writes:

    bench/closed_loop_table.py ROWS.csv

Per hidden case, the answers before and after the first proposed test was run and added: how
many were right (for the null: `none`, or `footprint` where the stated footprint is wrong, as
the issue of record counts it), each with its 95 % Clopper-Pearson interval, and how many named a
wrong mechanism; how the hidden mechanism's held-out gain moved with the added test (where the
rows have it: bench/closed_loop_row.py); then the answers that changed. Last, the totals the acceptance rates are read
from: hidden effects named, nulls right and wrong mechanisms, before and after.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from success_table import clopper_pearson, seeds_text  # noqa: E402

NOT_A_MECHANISM = ("none", "unexplained", "footprint", "normal_law")
ORDER = ["none", "velocity_dependent_friction", "amplitude_dependent_restitution", "eccentric_mass",
         "base_imperfection", "vertical_excitation", "floor_compliance", "out_of_plane_loss", "sensor_delay"]


def right(case, cause):
    return cause in ("none", "footprint") if case == "none" else cause == case


def wrong_mechanism(case, cause):
    return not right(case, cause) and cause not in NOT_A_MECHANISM


def seeds_of(rows):
    seeds = [int(r["seed"]) for r in rows]
    return str(seeds[0]) if len(seeds) == 1 else seeds_text(seeds)


def median(values):
    values = sorted(values)
    middle = len(values) // 2
    return values[middle] if len(values) % 2 else 0.5 * (values[middle - 1] + values[middle])


def gain_moved(rows):
    """In how many sets the hidden mechanism's held-out gain rose once the proposed test was added."""
    pairs = [(float(r["hidden_gain_before"]), float(r["hidden_gain_after"])) for r in rows
             if r.get("hidden_gain_before") and r.get("hidden_gain_after")]
    if not pairs:
        return "-"
    return "%d of %d (%.3g -> %.3g)" % (sum(a > b for b, a in pairs), len(pairs), median([b for b, _ in pairs]),
                                        median([a for _, a in pairs]))


def rate(k, n):
    low, high = clopper_pearson(k, n)
    return "%d of %d (%.0f to %.0f %%)" % (k, n, 100 * low, 100 * high)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: closed_loop_table.py ROWS.csv")
    rows = list(csv.DictReader(open(sys.argv[1])))
    present = set(r["hidden"] for r in rows)
    cases = [c for c in ORDER if c in present] + sorted(present - set(ORDER))
    print("| hidden | seeds | right before | right after, the proposed test added | wrong mechanism "
          "(before, after) | hidden among the plan's candidates | hidden's held-out gain rose (median before -> after) | answers that changed (seed: before -> after; "
          "the test proposed, its separation) |")
    print("|---|---|---|---|---|---|---|---|")
    totals = {"named": [0, 0, 0], "null": [0, 0, 0], "wrong": [0, 0, 0]}
    for case in cases:
        mine = sorted((r for r in rows if r["hidden"] == case), key=lambda r: int(r["seed"]))
        before = sum(right(case, r["cause_before"]) for r in mine)
        after = sum(right(case, r["cause_after"]) for r in mine)
        wrong = (sum(wrong_mechanism(case, r["cause_before"]) for r in mine),
                 sum(wrong_mechanism(case, r["cause_after"]) for r in mine))
        changes = ["%s: %s -> %s (%s; %s)" % (r["seed"], r["cause_before"], r["cause_after"], r["proposed"],
                                              r["separation"])
                   for r in mine if r["cause_before"] != r["cause_after"]]
        among = "-" if case == "none" else "%d of %d" % (sum(case in r["candidates"].split() for r in mine), len(mine))
        moved = gain_moved(mine) if case != "none" else "-"
        label = "none (baseline + noise)" if case == "none" else "`%s`" % case
        print("| %s | %s | %s | %s | %d, %d | %s | %s | %s |" % (label, seeds_of(mine), rate(before, len(mine)),
                                                                rate(after, len(mine)), wrong[0], wrong[1], among,
                                                                moved, "; ".join(changes) or "-"))
        key = "null" if case == "none" else "named"
        totals[key][0] += before
        totals[key][1] += after
        totals[key][2] += len(mine)
        if case != "none":  # a mechanism named on a null is counted against the null's rate above
            totals["wrong"][0] += wrong[0]
            totals["wrong"][1] += wrong[1]
            totals["wrong"][2] += len(mine)
    print()
    for key, text in (("named", "Hidden effects named"), ("null", "Nulls answered none or footprint"),
                      ("wrong", "Hidden effects given a wrong mechanism")):
        b, a, n = totals[key]
        if n:
            print("%s: before %s, after %s." % (text, rate(b, n), rate(a, n)))
    times = [float(r[w]) for r in rows for w in ("wall_before_s", "wall_after_s") if r[w]]
    if times:
        times.sort()
        print("Wall time of a diagnosis (s): median %.0f, largest %.0f, over %d diagnoses." %
              (median(times), times[-1], len(times)))


if __name__ == "__main__":
    main()
