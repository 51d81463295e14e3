"""Site risk of a caskdem fragility: the hazard curve, the family of fragility curves (mean,
and the 5, 50 and 95 % confidence members) and the contribution of each stretch of the
hazard curve to the mean annual frequency.

Usage: plot_risk.py RISK.json OUT.png
Reads the JSON written by `caskdem risk` (docs/risk.md).
"""
import json
import math
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

Z95 = 1.6448536269514722


def phi(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


def main(json_file, png_file):
    with open(json_file) as f:
        report = json.load(f)
    hazard = report["hazard"]
    a = np.array(hazard["intensity"])
    h = np.array(hazard["annual_frequency"])
    label = "%s [%s]" % (hazard["measure"], hazard["unit"])
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(15, 4.6))

    left.loglog(a, h, "k.-")
    left.axhline(report["target_annual_frequency"], color="grey", ls=":", label="target")
    if "design_basis" in report:
        left.axvline(report["design_basis"], color="grey", ls="--", label="design basis")
    left.set_xlabel(label)
    left.set_ylabel("annual frequency of exceedance")
    left.set_title("hazard: " + hazard["source"].split("/")[-1], fontsize=9)
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8)

    grid = np.geomspace(a[0], a[-1], 400)
    for k, state in enumerate(report["limit_states"]):
        colour = "C%d" % k
        m, br, bu, bc = state["median"], state["beta_r"], state["beta_u"], state["beta_c"]
        middle.plot(grid, [phi(math.log(x / m) / bc) for x in grid], color=colour, lw=2,
                    label="%s mean (HCLPF %.3g %s)" % (state["name"], state["hclpf_conservative"], hazard["unit"]))
        if bu > 0.0:
            for q, style in ((-Z95, ":"), (0.0, "--"), (Z95, ":")):
                middle.plot(grid, [phi((math.log(x / m) + bu * q) / br) for x in grid], color=colour, ls=style, lw=1)
        shares = np.array(state["segment_annual_frequency"]) / state["mean_annual_frequency"]
        centres = np.sqrt(a[:-1] * a[1:])
        right.step(centres, shares, where="mid", color=colour,
                   label="%s: %.3g /yr (5-95 %%: %.3g-%.3g)" % (state["name"], state["mean_annual_frequency"],
                                                                 state["fractile_05_annual_frequency"],
                                                                 state["fractile_95_annual_frequency"]))
    middle.set_xscale("log")
    middle.set_xlabel(label)
    middle.set_ylabel("probability of the limit state")
    middle.set_title("fragility: mean (solid), 50 % (dashed), 5 and 95 % (dotted)", fontsize=9)
    middle.grid(True, which="both", alpha=0.3)
    middle.legend(fontsize=8)
    right.set_xscale("log")
    right.set_xlabel(label)
    right.set_ylabel("share of the mean annual frequency, per hazard segment")
    right.set_title("which intensities contribute", fontsize=9)
    right.grid(True, which="both", alpha=0.3)
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png_file, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
