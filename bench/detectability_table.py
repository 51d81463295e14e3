"""The diagnoses' answers (bench/diagnosis_success.sh rows) beside what the truth itself scores
on the same data sets (bench/truth_detectability.sh rows): a Markdown table, one row per
hidden mechanism. A miss where the truth is significant is the search's or the objective's;
in a miss where it is not, the mechanism at its true values does not pass the diagnosis's own
test: judged so, the data do not show it beyond noise. Given the answers' -parameters.csv too (seeds where it has the hidden
model's training objective), a miss where the truth is significant says whether the fit ended
above the truth's J (the search did not reach it) or not (the objective prefers another point,
which loses on the held-out tests).

    detectability_table.py ANSWERS.csv TRUTH.csv [ANSWERS-parameters.csv]
"""
import csv
import sys

from truth_row import failed_criteria


def failing(row):
    """Which of the significance criteria the truth fails, with its value."""
    return ", ".join(failed_criteria(float(row["truth_gain"]), float(row["truth_bic_delta"]),
                                     int(row["heldout_tests_improved"]), int(row["heldout_tests"])))


def seed_list(rows, describe=None):
    if not rows:
        return "-"
    return "; ".join(r["seed"] + (" (%s)" % describe(r) if describe else "") for r in rows)


def fitted_objectives(path):
    """The hidden model's training J per (hidden, seed), from the answers' -parameters.csv."""
    objective = {}
    for r in csv.DictReader(open(path)):
        if r["hidden"] != "none" and r["training_objective"]:
            objective[(r["hidden"], r["seed"])] = float(r["training_objective"])
    return objective


answers = {(r["hidden"], r["seed"]): r for r in csv.DictReader(open(sys.argv[1]))}
truths = list(csv.DictReader(open(sys.argv[2])))
fitted = fitted_objectives(sys.argv[3]) if len(sys.argv) > 3 else {}


def against_fit(row):
    """The fit's J against the truth's, where the fit's is known."""
    key = (row["hidden"], row["seed"])
    if key not in fitted:
        return "fit's J not recorded"
    truth = float(row["truth_objective"])
    return "J %.3g at the fit, %.3g at the truth" % (fitted[key], truth)


print("| hidden | data sets | right | truth significant | right, truth not significant | misses, truth significant | misses, truth not significant (what fails at the truth) |")
print("|---|---|---|---|---|---|---|")
for hidden in dict.fromkeys(t["hidden"] for t in truths):
    mine = [t for t in truths if t["hidden"] == hidden and (hidden, t["seed"]) in answers]
    right = [t for t in mine if answers[(hidden, t["seed"])]["cause"] == hidden]
    missed = [t for t in mine if t not in right]
    detectable = [t for t in mine if t["truth_significant"] == "true"]
    print("| `%s` | %d | %d | %d | %d | %s | %s |" % (
        hidden, len(mine), len(right), len(detectable), sum(t["truth_significant"] != "true" for t in right),
        seed_list([t for t in missed if t["truth_significant"] == "true"], against_fit),
        seed_list([t for t in missed if t["truth_significant"] != "true"], failing)))
