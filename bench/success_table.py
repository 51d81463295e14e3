#!/usr/bin/python3
"""The diagnosis's success and false-alarm rates as a Markdown table, from the rows that
bench/diagnosis_success.sh writes:

    bench/success_table.py ROWS.csv [EARLIER_ROWS.csv]

Per hidden case: the data sets, how many got the hidden cause ("none" for the null case),
how many were missed (answered "none"), how many were answered "unexplained" or "footprint"
(the model misfits, or another footprint rule fits; not a mechanism) and how many named a
wrong mechanism, with the 95 %
Clopper-Pearson interval of the success rate. With a second file (the same data sets diagnosed
by other code), its successes on the data sets both files hold and each answer that changed.
"""
import csv
import math
import sys


def binomial_cdf(k, n, p):
    """P(X <= k) for X ~ Binomial(n, p)."""
    if k < 0:
        return 0.0
    if k >= n:
        return 1.0
    return sum(math.comb(n, i) * p**i * (1.0 - p) ** (n - i) for i in range(k + 1))


def solve(f, target):
    """The p in [0, 1] where the decreasing f(p) crosses target (bisection)."""
    low, high = 0.0, 1.0
    for _ in range(60):
        middle = 0.5 * (low + high)
        if f(middle) > target:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


def clopper_pearson(k, n, level=0.95):
    """Exact binomial interval (Clopper & Pearson 1934)."""
    tail = 0.5 * (1.0 - level)
    lower = 0.0 if k == 0 else solve(lambda p: binomial_cdf(k - 1, n, p), 1.0 - tail)
    upper = 1.0 if k == n else solve(lambda p: binomial_cdf(k, n, p), tail)
    return lower, upper


def read(path):
    rows = list(csv.DictReader(open(path)))
    return {(r["hidden"], int(r["seed"])): r for r in rows}


def gain_text(row):
    """The hidden mechanism's held-out gain; for the null case, the top mechanism's."""
    gain = row["top_gain"] if row["hidden"] == "none" else row["hidden_gain"]
    return "%.2f" % float(gain) if gain else "-"


def seeds_text(seeds):
    seeds = sorted(seeds)
    if seeds == list(range(seeds[0], seeds[-1] + 1)):
        return "%d to %d" % (seeds[0], seeds[-1])
    return ", ".join(str(s) for s in seeds)


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: success_table.py ROWS.csv [EARLIER_ROWS.csv]")
    now = read(sys.argv[1])
    earlier = read(sys.argv[2]) if len(sys.argv) == 3 else None
    order = ["none", "velocity_dependent_friction", "amplitude_dependent_restitution", "eccentric_mass",
             "base_imperfection", "vertical_excitation", "floor_compliance", "out_of_plane_loss", "sensor_delay"]
    present = set(hidden for hidden, _ in now)
    cases = [c for c in order if c in present] + sorted(present - set(order))
    header = "| hidden | seeds | right | 95 % interval | missed | unexplained or footprint | wrong mechanism |"
    rule = "|---|---|---|---|---|---|---|"
    if earlier is not None:
        header += " right with the earlier code | answers that changed (earlier -> now; held-out gain of the hidden mechanism, of the top one for none) |"
        rule += "---|---|"
    print(header)
    print(rule)
    totals = [0, 0, 0, 0]
    for case in cases:
        keys = sorted(k for k in now if k[0] == case)
        rows = [now[k] for k in keys]
        right = sum(r["cause"] == case for r in rows)
        missed = sum(r["cause"] == "none" for r in rows) if case != "none" else 0
        # Not a mechanism: the model misfits and nothing explains it, or another footprint fits.
        flagged = [r for r in rows if r["cause"] in ("unexplained", "footprint") and r["cause"] != case]
        wrong = len(rows) - right - missed - len(flagged)
        low, high = clopper_pearson(right, len(rows))
        label = "none (baseline + noise)" if case == "none" else "`%s`" % case
        wrong_text = str(wrong)
        if wrong:
            names = ", ".join("%s on %s" % (r["cause"], r["seed"]) for r in rows
                              if r["cause"] not in (case, "none", "unexplained", "footprint"))
            wrong_text += " (" + names + ")"
        flagged_text = str(len(flagged))
        if flagged:
            flagged_text += " (" + ", ".join("%s on %s" % (r["cause"], r["seed"]) for r in flagged) + ")"
        line = "| %s | %s | %d of %d | %.0f to %.0f %% | %s | %s | %s |" % (
            label, seeds_text([k[1] for k in keys]), right, len(rows), 100 * low, 100 * high,
            missed if case != "none" else "-", flagged_text, wrong_text)
        totals[0] += right
        totals[1] += len(rows)
        if earlier is not None:
            shared = [k for k in keys if k in earlier]
            before = sum(earlier[k]["cause"] == case for k in shared)
            changes = []
            for k in shared:
                a, b = earlier[k], now[k]
                if a["cause"] != b["cause"]:
                    changes.append("%d: %s (%s) -> %s (%s)" % (k[1], a["cause"], gain_text(a), b["cause"], gain_text(b)))
            line += " %d of %d | %s |" % (before, len(shared), "; ".join(changes) or "-")
            totals[2] += before
            totals[3] += len(shared)
        print(line)
    print()
    text = "All cases: %d of %d right" % (totals[0], totals[1])
    if earlier is not None:
        text += "; the earlier code, on the data sets both hold: %d of %d" % (totals[2], totals[3])
    print(text + ".")


if __name__ == "__main__":
    main()
