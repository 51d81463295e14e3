"""Fragility curves of a caskdem ensemble: fitted lognormal curves with their bootstrap
bands and the stripe probabilities with their binomial intervals. A curve whose fit is rejected
(the test with the motions clustered, docs/ensemble-file.md) is dashed and says so; a rocking or
sliding state's casks that exceeded while standing are the hollow markers; a state with the same
stripes as another says so. With epistemic parameters, also each outer point's curve and the
family's 5 % and 95 % confidence curves (median A_m exp(-+1.645 beta_U), spread beta_R;
docs/risk.md). The axis names the scale: a 1/N model's intensities, with the full-size cask's
factor.

Usage: plot_fragility.py RESULT.h5 OUT.png
Reads the layout written by `caskdem ensemble` (docs/output.md).
"""
import math
import sys
import textwrap

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

UNITS = {"pga": ("PGA [g]", 1.0 / 9.80665), "pgv": ("PGV [cm/s]", 100.0),
         "pga_ratio": ("PGA / (g tan alpha)", 1.0), "pgv_ratio": ("PGV p / (g tan alpha)", 1.0),
         "sa": ("Sa(T) [g]", 1.0 / 9.80665)}
# The unit a median is read in, beside it in the legend (the ratios have none).
MEDIAN_UNITS = {"pga": " g", "pgv": " cm/s", "pga_ratio": "", "pgv_ratio": "", "sa": " g"}


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def phi(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


def axis_label(f, measure):
    label, factor = UNITS[measure]
    if measure == "sa":
        label = "Sa(%g s, %g %%) [g]" % (f.attrs["intensity_period_s"], 100.0 * f.attrs["intensity_damping_ratio"])
    if "pair_measure" in f.attrs and measure in ("pga", "pgv"):
        # A 3D ensemble scales each station's pair by one measure of it.
        pair = {"rotd50": "RotD50", "rotd100": "RotD100", "geometric_mean": "geometric-mean"}
        label = pair.get(text(f.attrs["pair_measure"]), text(f.attrs["pair_measure"])) + " " + label
    scale = float(f.attrs.get("model_scale", 1.0))
    if scale > 1.0:
        full = {"pgv": "x %.3g at full size" % math.sqrt(scale),
                "sa": "the same at full size, at %.3g times the period" % math.sqrt(scale)}.get(measure,
                                                                                                "the same at full size")
        label += " of the table, on the 1/%g model (%s)" % (scale, full)
    elif scale == 0.0:
        label += " of the table (motions on models of several scales)"
    else:
        label += " of the table"
    return label, factor


def read_state(name, group, factor):
    state = {"name": name, "level": group["level"][:] * factor, "p": group["probability"][:],
             "low": group["probability_lower"][:], "high": group["probability_upper"][:],
             "n": group["trials"][:], "fitted": int(group.attrs["fitted"]),
             "order": int(group.attrs.get("order", 0)), "same_as": text(group.attrs.get("same_as", ""))}
    if "standing_count" in group and not state["same_as"]:
        n = np.maximum(state["n"], 1)
        state["standing"] = group["standing_count"][:] / n
    if state["fitted"]:
        state["median"] = float(group.attrs["median"]) * factor
        state["beta"] = float(group.attrs["log_std"])
        state["band_im"] = group["band_im"][:] * factor
        state["band_low"] = group["band_lower"][:]
        state["band_high"] = group["band_upper"][:]
        if "fit_rejected" in group.attrs:
            state["rejected"] = int(group.attrs["fit_rejected"])
            state["test_p"] = float(group.attrs["fit_test_p_value"])
            state["rho"] = float(group.attrs["record_to_record"])
    else:
        state["reason"] = text(group.attrs["not_fitted_because"])
    if "epistemic" in group:
        e = group["epistemic"]
        # Unfitted outer points hold 0 (docs/output.md).
        outer = zip(e["outer_median"][:], e["outer_log_std"][:])
        state["outer"] = [(m * factor, b) for m, b in outer if m > 0.0 and b > 0.0]
        if int(e.attrs["fitted"]) and float(e.attrs["beta_r"]) > 0.0:
            state["family"] = {k: float(e.attrs[k]) for k in ("median", "beta_r", "beta_u")}
            state["family"]["median"] *= factor
    return state


def main(result_file, png_file):
    with h5py.File(result_file, "r") as f:
        measure = text(f.attrs["intensity_measure"])
        label, factor = axis_label(f, measure)
        unit = MEDIAN_UNITS[measure]
        title = text(f.attrs.get("title", ""))
        completed = int(f.attrs["completed"])
        total = int(f.attrs["realisations"])
        states = sorted((read_state(name, group, factor) for name, group in f["limit_states"].items()),
                        key=lambda s: s["order"])

    fig, ax = plt.subplots(figsize=(13.0, 6.0))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, s in enumerate(states):
        colour = colours[i % len(colours)]
        errors = np.vstack([s["p"] - s["low"], s["high"] - s["p"]])
        x = s["band_im"] if s["fitted"] else np.linspace(0.5 * s["level"].min(), 1.5 * s["level"].max(), 201)
        family = s.get("family")
        family_text = ("; A_m %.3g%s, beta_R %.2f, beta_U %.2f" % (family["median"], unit, family["beta_r"],
                                                                    family["beta_u"]) if family else "")
        if s["fitted"]:
            curve = [phi(math.log(v / s["median"]) / s["beta"]) for v in x]
            rejected = s.get("rejected", 0)
            ax.fill_between(x, s["band_low"], s["band_high"], color=colour, alpha=0.18, lw=0)
            name = "%s: median %.3g%s, beta %.2f" % (s["name"], s["median"], unit, s["beta"])
            if "test_p" in s:
                name += ("; fit REJECTED (p %.2g)" if rejected else "; fit holds (p %.2g)") % s["test_p"]
            ax.plot(x, curve, color=colour, ls="--" if rejected else "-", label=name + family_text)
        else:
            # A reason can be long: wrapped, so that the legend stays inside the figure.
            name = "%s: no curve (%s)" % (s["name"], s["reason"])
            ax.plot([], [], color=colour, label=textwrap.fill(name + family_text, 60))
        if s["same_as"]:
            # Drawn over the other state's points: said in the legend, with why.
            ax.plot([], [], ls="none", label=textwrap.fill("  %s: %s" % (s["name"], s["same_as"]), 60))
        ax.errorbar(s["level"], s["p"], yerr=errors, fmt="o", color=colour, ms=4, capsize=2)
        if "standing" in s:
            ax.plot(s["level"], s["standing"], "o", mfc="none", color=colour, ms=6,
                    label="  %s: exceeded while standing" % s["name"])
        for median, beta in s.get("outer", []):
            ax.plot(x, [phi(math.log(v / median) / beta) for v in x], color=colour, lw=0.5, alpha=0.35)
        if family:
            # The members whose median is exceeded with 95 % (z < 0) and 5 % confidence.
            for z in (-1.645, 1.645):
                median = family["median"] * math.exp(z * family["beta_u"])
                ax.plot(x, [phi(math.log(v / median) / family["beta_r"]) for v in x], color=colour, lw=1.0, ls=":")
    ax.set_xlabel(textwrap.fill(label, 100), fontsize=9)
    ax.set_ylabel("probability of exceedance")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(True, lw=0.3)
    # Beside the axes, where it hides no point.
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    caption = ("%s\n%d/%d realisations; curves: lognormal MLE (dashed: fit rejected at 5 %% with the motions "
               "clustered), band: bootstrap over records;\npoints: stripes with Clopper-Pearson intervals "
               "(a cask that tipped over exceeds every limit state)" % (title, completed, total))
    if any(s.get("outer") for s in states):
        caption += "\nthin: each outer point's curve; dotted: the family's 95 % and 5 % confidence curves (beta_R)"
    ax.set_title(caption, fontsize=8)
    fig.tight_layout()
    fig.savefig(png_file, dpi=130)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_fragility.py RESULT.h5 OUT.png")
    main(sys.argv[1], sys.argv[2])
