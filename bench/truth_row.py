"""One row of bench/truth_detectability.sh: the hidden model at its true values against the
calibrated baseline, scored as diagnose scores a candidate (src/diagnosis/diagnose.cpp, score):
significant when the held-out gain is at least 0.2, the BIC lower by at least 10 and the
held-out loss lower on at least half of the held-out tests (DiagnosisOptions' defaults).

    truth_row.py BASELINE_EVALUATION.json TRUTH_EVALUATION.json HIDDEN SEED
"""
import json
import sys

MINIMUM_GAIN, MAXIMUM_BIC_DELTA, MINIMUM_IMPROVED_FRACTION = 0.2, -10.0, 0.5

baseline, truth = (json.load(open(path)) for path in sys.argv[1:3])
hidden, seed = sys.argv[3], sys.argv[4]
heldout = [t["name"] for t in baseline["tests"] if t["role"] == "heldout"]
loss = {which: {t["name"]: t["loss"] for t in e["tests"]} for which, e in (("baseline", baseline), ("truth", truth))}
improved = sum(loss["truth"][name] < loss["baseline"][name] for name in heldout)
gain = 1.0 - truth["heldout_error"] / baseline["heldout_error"] if baseline["heldout_error"] > 0 else 0.0
bic_delta = truth["bic"] - baseline["bic"]
# The training test that holds most of the truth's J, and the baseline's loss on it.
training = [t["name"] for t in truth["tests"] if t["role"] == "training"]
worst = max(training, key=lambda name: loss["truth"][name])
significant = gain >= MINIMUM_GAIN and bic_delta <= MAXIMUM_BIC_DELTA and improved >= MINIMUM_IMPROVED_FRACTION * len(heldout)
print(",".join([hidden, seed, "%.4g" % baseline["training_objective"], "%.4g" % truth["training_objective"],
                "%.4g" % baseline["heldout_error"], "%.4g" % truth["heldout_error"], "%.4f" % gain, "%.2f" % bic_delta,
                str(improved), str(len(heldout)), str(significant).lower(), worst, "%.4g" % loss["truth"][worst],
                "%.4g" % loss["baseline"][worst]]))
