#!/usr/bin/env python3
"""The intensity measures set side by side on ensembles' results: for each limit state of each
fragility table (NAME-fragility.json, written by caskdem ensemble), every measure's log-std
beta, its record-to-record share rho and its fit test's p with the motions clustered
(docs/ensemble-file.md, "How far to trust a curve").

Usage: bench/measure_table.py RESULT-fragility.json ...
Prints a markdown table; the measure with the smallest beta of a limit state is in bold.
"""
import json
import os
import sys


def main(files):
    print("| ensemble | limit state | " + " | ".join(["measure: beta, rho, p"] * 1) + " |")
    print("|---|---|---|")
    for path in files:
        with open(path) as f:
            report = json.load(f)
        name = os.path.basename(path).replace("-fragility.json", "")
        for state in report["limit_states"]:
            if not state.get("fitted"):
                print("| %s | %s | no curve: %s |" % (name, state["name"], state.get("not_fitted_because", "")))
                continue
            if state.get("same_as"):
                continue  # the same stripes as another state: the same numbers
            fitted = [m for m in state["measures"] if m["fitted"]]
            best = min(fitted, key=lambda m: m["log_std"]) if fitted else None
            cells = []
            for m in state["measures"]:
                if not m["fitted"]:
                    cells.append("%s: no curve" % m["name"])
                    continue
                t = m["test"]
                text = "%s%s: %.3f, %.2f, %.2f%s" % (m["name"], " (design)" if m["design"] else "", m["log_std"],
                                                      t["record_to_record"], t["p_value"],
                                                      " rejected" if t["rejected"] else "")
                cells.append("**%s**" % text if m is best else text)
            print("| %s | %s | %s |" % (name, state["name"], "; ".join(cells)))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
