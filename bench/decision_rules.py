#!/usr/bin/python3
"""Decision rules of `caskdem diagnose` compared on the same fits.

    bench/decision_rules.py KEEP_DIR [KEEP_DIR ...] [--sweep]

KEEP_DIR holds the diagnosis.json of each data set that bench/diagnosis_success.sh kept
(KEEP=DIR): EFFECT-SEED-diagnosis.json. The fits do not depend on the decision rule (the
search for a second effect is off in these runs), so the cause each rule would give follows
from the ranking alone:

  cause = the first candidate, by held-out gain, with gain >= G, BIC delta <= B, at least
          half its held-out tests improved and (common rule) not at its off value;
          else "footprint" if another footprint rule was kept; else "unexplained" if the
          baseline is inadequate; else "none".

Rules:
  common  the held-out tests of a candidate and the baseline judged at common tolerances
          (the larger of the two per test and measure): diagnosis.json's heldout_gain.
  own     each model judged at its own tolerances, widened by its own fit's spread (the
          rule before the common one): 1 - candidate.fit.heldout_error / baseline.heldout_error.
          Its improved-test count is the common rule's (per-test losses at own tolerances are
          not kept), and a candidate at its off value is not excluded.

Prints per rule and hidden effect: sets, named, missed (none), unexplained or footprint,
wrong mechanism, with the 95 % Clopper-Pearson interval of the success rate. With --sweep,
also the false-alarm rate on the null sets and the detection rate over all effects for a
grid of (G, B), to choose thresholds from the null data.
"""
import glob
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from success_table import clopper_pearson  # noqa: E402

MINIMUM_IMPROVED_FRACTION = 0.5


def load(directories):
    sets = []
    for directory in directories:
        for path in sorted(glob.glob(os.path.join(directory, "*-diagnosis.json"))):
            name = os.path.basename(path)[: -len("-diagnosis.json")]
            effect, seed = name.rsplit("-", 1)
            sets.append((effect, int(seed), json.load(open(path))))
    return sets


def gain(rule, candidate, baseline):
    if rule == "common":
        return candidate["heldout_gain"]
    reference = baseline["heldout_error"]
    return 1.0 - candidate["fit"]["heldout_error"] / reference if reference > 0.0 else 0.0


def cause(d, rule, minimum_gain, maximum_bic_delta):
    heldout = len(d["tests"]["heldout"])
    ranked = sorted(d["ranking"], key=lambda c: -gain(rule, c, d["baseline"]))
    for c in ranked:
        if rule == "common" and c["at_off_value"]:
            continue
        if (gain(rule, c, d["baseline"]) >= minimum_gain and c["information_criterion_delta"] <= maximum_bic_delta
                and c["heldout_tests_improved"] >= MINIMUM_IMPROVED_FRACTION * heldout):
            return c["mechanism"]
    if d["footprint_changed"]:
        return "footprint"
    if not d["baseline"]["adequacy"]["adequate"]:
        return "unexplained"
    return "none"


def tally(sets, rule, minimum_gain, maximum_bic_delta):
    table = {}
    for effect, _, d in sets:
        answer = cause(d, rule, minimum_gain, maximum_bic_delta)
        row = table.setdefault(effect, {"sets": 0, "named": 0, "missed": 0, "unexplained": 0, "wrong": 0})
        row["sets"] += 1
        if answer == effect:
            row["named"] += 1
        elif answer == "none":
            row["missed"] += 1
        elif answer in ("unexplained", "footprint"):
            row["unexplained"] += 1
        else:
            row["wrong"] += 1
    return table


def interval_text(k, n):
    low, high = clopper_pearson(k, n)
    return "%d/%d (%.0f %%, %.0f-%.0f %%)" % (k, n, 100.0 * k / n, 100.0 * low, 100.0 * high)


def print_table(sets, rule, minimum_gain, maximum_bic_delta):
    table = tally(sets, rule, minimum_gain, maximum_bic_delta)
    print("\nrule %s, gain >= %.2f, BIC delta <= %.0f" % (rule, minimum_gain, maximum_bic_delta))
    print("| hidden | sets | right (95 % interval) | missed | unexplained/footprint | wrong mechanism |")
    print("|---|---|---|---|---|---|")
    effects = sorted(table, key=lambda e: (e != "none", e))
    totals = {"sets": 0, "named": 0, "wrong": 0}
    for effect in effects:
        row = table[effect]
        right = row["named"]
        print("| %s | %d | %s | %d | %d | %d |" % (effect, row["sets"], interval_text(right, row["sets"]),
                                                row["missed"], row["unexplained"], row["wrong"]))
        if effect != "none":
            for key in totals:
                totals[key] += row[key]
    if totals["sets"]:
        print("| all effects | %d | %s | | | %s |" % (totals["sets"], interval_text(totals["named"], totals["sets"]),
                                                     interval_text(totals["wrong"], totals["sets"])))


def sweep(sets, rule):
    null = [s for s in sets if s[0] == "none"]
    effects = [s for s in sets if s[0] != "none"]
    print("\nrule %s: false alarms on the null and effects named, by threshold" % rule)
    print("| gain >= | BIC delta <= | false alarms | named | wrong |")
    print("|---|---|---|---|---|")
    for minimum_gain in (-1.0, 0.0, 0.05, 0.1, 0.15, 0.2, 0.3):
        for maximum_bic_delta in (0.0, -5.0, -10.0, -15.0, -20.0, -30.0):
            alarms = sum(cause(d, rule, minimum_gain, maximum_bic_delta) != "none" for _, _, d in null)
            named = sum(cause(d, rule, minimum_gain, maximum_bic_delta) == e for e, _, d in effects)
            wrong = sum(cause(d, rule, minimum_gain, maximum_bic_delta) not in (e, "none", "unexplained", "footprint")
                        for e, _, d in effects)
            print("| %.2f | %.0f | %d/%d | %d/%d | %d |" % (minimum_gain, maximum_bic_delta, alarms, len(null), named,
                                                          len(effects), wrong))


def main():
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not arguments:
        sys.exit(__doc__)
    sets = load(arguments)
    for rule in ("own", "common"):
        print_table(sets, rule, 0.2, -10.0)
    if "--sweep" in sys.argv:
        for rule in ("own", "common"):
            sweep(sets, rule)


if __name__ == "__main__":
    main()
