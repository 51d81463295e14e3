#!/usr/bin/python3
"""CSV rows of a fit's parameters beside the truth, for bench/parameter_coverage.py.

    /usr/bin/python3 bench/parameter_rows.py RESULT.json TRUTH.json HIDDEN SEED [METHOD]

RESULT.json is a diagnosis.json (the fit of the hidden model, the baseline for none) or a
calibration.json (its baseline); TRUTH.json is the generator's. One row per parameter that
the truth knows: hidden, seed, model, parameter, truth, fitted, standard_error (empty when
there is none: the mechanism switched off, the curvature not positive definite, or the value on
its search bound), at_search_bound, training_objective, training_residuals, and METHOD when
given (calibration_coverage.sh's --uncertainty).
"""
import json
import sys

MEASURES_PER_TEST = 10  # measures.h, measure_names()


def main(result_path, truth_path, hidden, seed, method=None):
    result, made = json.load(open(result_path)), json.load(open(truth_path))
    # caskdem's generator lists every parameter of its model; the independent generator
    # (tests/independent) lists its own under "true", of which friction and stiffness_scale
    # mean what the diagnosis's do.
    truth = made["parameters"] if "parameters" in made else made.get("true", {})
    if "ranking" in result:
        fit = result["baseline"] if hidden == "none" else next(
            r["fit"] for r in result["ranking"] if r["mechanism"] == hidden)
        training = result["tests"]["training"]
    else:
        fit, training = result, result["training_tests"]
    for name, p in sorted(fit["parameters"].items()):
        if name not in truth:
            continue
        se = p["standard_error"]
        fields = [hidden, seed, fit["model"], name, "%.6g" % truth[name], "%.6g" % p["value"],
                  "" if se is None else "%.4g" % se, str(p["at_search_bound"]).lower(),
                  "%.4f" % fit["training_objective"], str(len(training) * MEASURES_PER_TEST)]
        print(",".join(fields + ([method] if method else [])))


if __name__ == "__main__":
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    main(*sys.argv[1:])
