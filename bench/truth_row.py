"""One row of bench/truth_detectability.sh: the hidden model at its true values against the
calibrated baseline, scored as diagnose scores a candidate (src/diagnosis/diagnose.cpp, score):
significant when the held-out gain is at least 0.2, the BIC lower by at least 10 and the
held-out loss lower on at least half of the held-out tests (DiagnosisOptions' defaults).

    truth_row.py BASELINE_EVALUATION.json TRUTH_EVALUATION.json HIDDEN SEED
"""
import json
import sys

MINIMUM_GAIN, MAXIMUM_BIC_DELTA, MINIMUM_IMPROVED_FRACTION = 0.2, -10.0, 0.5


def failed_criteria(gain, bic_delta, improved, heldout):
    """The significance criteria a model fails, each with its value (empty: significant)."""
    failed = []
    if gain < MINIMUM_GAIN:
        failed.append("gain %.2f" % gain)
    if bic_delta > MAXIMUM_BIC_DELTA:
        failed.append("BIC %+.1f" % bic_delta)
    if improved < MINIMUM_IMPROVED_FRACTION * heldout:
        failed.append("%d of %d tests better" % (improved, heldout))
    return failed


def main(baseline_path, truth_path, hidden, seed):
    baseline, truth = json.load(open(baseline_path)), json.load(open(truth_path))
    heldout = [t["name"] for t in baseline["tests"] if t["role"] == "heldout"]
    loss = {which: {t["name"]: t["loss"] for t in e["tests"]} for which, e in (("baseline", baseline), ("truth", truth))}
    improved = sum(loss["truth"][name] < loss["baseline"][name] for name in heldout)
    gain = 1.0 - truth["heldout_error"] / baseline["heldout_error"] if baseline["heldout_error"] > 0 else 0.0
    bic_delta = truth["bic"] - baseline["bic"]
    # The training test that holds most of the truth's J, and the baseline's loss on it.
    training = [t["name"] for t in truth["tests"] if t["role"] == "training"]
    worst = max(training, key=lambda name: loss["truth"][name])
    significant = not failed_criteria(gain, bic_delta, improved, len(heldout))
    print(",".join([hidden, seed, "%.4g" % baseline["training_objective"], "%.4g" % truth["training_objective"],
                    "%.4g" % baseline["heldout_error"], "%.4g" % truth["heldout_error"], "%.4f" % gain,
                    "%.2f" % bic_delta, str(improved), str(len(heldout)), str(significant).lower(), worst,
                    "%.4g" % loss["truth"][worst], "%.4g" % loss["baseline"][worst]]))


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
