"""Site risk of a caskdem fragility: the hazard curve, the family of fragility curves (mean,
and where an epistemic beta_U was sampled the 5, 50 and 95 % confidence members) with both
HCLPF capacities, and the contribution of each stretch of the hazard curve to the mean annual
frequency. A curve whose ensemble fit was rejected is dashed and says so. Intensities are the
site's, full size (a 1/N model's curves taken there by the similarity law, as the JSON says).

Usage: plot_risk.py RISK.json OUT.png
Reads the JSON written by `caskdem risk` (docs/risk.md).
"""
import json
import math
import sys
import textwrap

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
    scale = report.get("similarity", 1.0)
    label = "%s [%s], %s" % (hazard["measure"], hazard["unit"],
                             "full size (the 1/%g model's curves taken there)" % scale if scale > 1.0 else "as given")
    fig, (left, middle, right) = plt.subplots(1, 3, figsize=(17, 5.6))

    left.loglog(a, h, "k.-", label="hazard")
    left.axhline(report["target_annual_frequency"], color="grey", ls=":", label="target")
    if "design_basis" in report:
        left.axvline(report["design_basis"], color="grey", ls="--", label="design basis")
    left.set_xlabel(textwrap.fill(label, 60), fontsize=9)
    left.set_ylabel("annual frequency of exceedance")
    left.set_title("hazard: " + hazard["source"].split("/")[-1], fontsize=9)
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=8)

    grid = np.geomspace(a[0], a[-1], 400)
    sampled = False
    for k, state in enumerate(report["limit_states"]):
        colour = "C%d" % k
        m, br, bu, bc = state["median"], state["beta_r"], state["beta_u"], state["beta_c"]
        rejected = state.get("fit_rejected", False)
        note = " (fit REJECTED)" if rejected else ""
        middle.plot(grid, [phi(math.log(x / m) / bc) for x in grid], color=colour, lw=2, ls="--" if rejected else "-",
                    label="%s%s: HCLPF %.3g %s (the lower), %.3g" % (state["name"], note, state["hclpf_lower"],
                                                                     hazard["unit"],
                                                                     max(state["hclpf_conservative"],
                                                                         state["hclpf_composite"])))
        middle.axvline(state["hclpf_lower"], color=colour, lw=0.8, ls=":")
        if bu > 0.0:
            sampled = True
            for q, style in ((-Z95, ":"), (0.0, "--"), (Z95, ":")):
                middle.plot(grid, [phi((math.log(x / m) + bu * q) / br) for x in grid], color=colour, ls=style, lw=1)
        shares = np.array(state["segment_annual_frequency"]) / state["mean_annual_frequency"]
        centres = np.sqrt(a[:-1] * a[1:])
        if state.get("fractiles_sampled", bu > 0.0):
            frequency = "%.3g /yr (5-95 %%: %.3g-%.3g)" % (state["mean_annual_frequency"],
                                                         state["fractile_05_annual_frequency"],
                                                         state["fractile_95_annual_frequency"])
        else:
            frequency = "%.3g /yr (fractiles not sampled)" % state["mean_annual_frequency"]
        right.step(centres, shares, where="mid", color=colour, ls="--" if rejected else "-",
                   label="%s%s: %s" % (state["name"], note, frequency))
    middle.set_xscale("log")
    middle.set_xlabel(textwrap.fill(label, 60), fontsize=9)
    middle.set_ylabel("probability of the limit state")
    middle.set_title("fragility: mean curves (dashed: fit rejected)" +
                     ("; thin: 50 % member (dashed), 5 and 95 % (dotted)" if sampled else "; beta_U not sampled") +
                     "\ndotted vertical lines: the lower HCLPF", fontsize=8)
    middle.grid(True, which="both", alpha=0.3)
    right.set_xscale("log")
    right.set_xlabel(textwrap.fill(label, 60), fontsize=9)
    right.set_ylabel("share of the mean annual frequency, per hazard segment")
    right.set_title("which intensities contribute", fontsize=9)
    right.grid(True, which="both", alpha=0.3)
    # The legends below the panels, where they hide nothing.
    middle.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16))
    right.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16))
    fig.tight_layout()
    fig.savefig(png_file, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
