"""Fragility curves of a caskdem ensemble: fitted lognormal curves with their bootstrap
bands and the stripe probabilities with their binomial intervals.

Usage: plot_fragility.py RESULT.h5 OUT.png
Reads the layout written by `caskdem ensemble` (docs/output.md).
"""
import math
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

UNITS = {"pga": ("PGA [g]", 1.0 / 9.80665), "pgv": ("PGV [cm/s]", 100.0),
         "pga_ratio": ("PGA / (g tan alpha)", 1.0), "pgv_ratio": ("PGV p / (g tan alpha)", 1.0),
         "sa": ("Sa(T) [g]", 1.0 / 9.80665)}


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def phi(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


def main(result_file, png_file):
    with h5py.File(result_file, "r") as f:
        measure = text(f.attrs["intensity_measure"])
        label, factor = UNITS[measure]
        if measure == "sa":
            label = "Sa(%g s, %g %%) [g]" % (f.attrs["intensity_period_s"], 100.0 * f.attrs["intensity_damping_ratio"])
        if "pair_measure" in f.attrs and measure in ("pga", "pgv"):
            # A 3D ensemble scales each station's pair by one measure of it.
            pair = {"rotd50": "RotD50", "rotd100": "RotD100", "geometric_mean": "geometric-mean"}
            label = pair.get(text(f.attrs["pair_measure"]), text(f.attrs["pair_measure"])) + " " + label
        title = text(f.attrs.get("title", ""))
        completed = int(f.attrs["completed"])
        total = int(f.attrs["realisations"])
        states = []
        for name, group in f["limit_states"].items():
            state = {"name": name, "level": group["level"][:] * factor, "p": group["probability"][:],
                     "low": group["probability_lower"][:], "high": group["probability_upper"][:],
                     "n": group["trials"][:], "fitted": int(group.attrs["fitted"])}
            if state["fitted"]:
                state["median"] = float(group.attrs["median"]) * factor
                state["beta"] = float(group.attrs["log_std"])
                state["band_im"] = group["band_im"][:] * factor
                state["band_low"] = group["band_lower"][:]
                state["band_high"] = group["band_upper"][:]
            else:
                state["reason"] = text(group.attrs["not_fitted_because"])
            states.append(state)

    fig, ax = plt.subplots(figsize=(8.5, 5.5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, s in enumerate(states):
        colour = colours[i % len(colours)]
        errors = np.vstack([s["p"] - s["low"], s["high"] - s["p"]])
        if s["fitted"]:
            x = s["band_im"]
            curve = [phi(math.log(v / s["median"]) / s["beta"]) for v in x]
            ax.fill_between(x, s["band_low"], s["band_high"], color=colour, alpha=0.18, lw=0)
            ax.plot(x, curve, color=colour,
                    label="%s: median %.3g, beta %.2f" % (s["name"], s["median"], s["beta"]))
        else:
            ax.plot([], [], color=colour, label="%s: no curve (%s)" % (s["name"], s["reason"]))
        ax.errorbar(s["level"], s["p"], yerr=errors, fmt="o", color=colour, ms=4, capsize=2)
    ax.set_xlabel(label)
    ax.set_ylabel("probability of exceedance")
    ax.set_ylim(-0.02, 1.02)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title("%s\n%d/%d realisations; curves: lognormal MLE, band: bootstrap over records; points: stripes "
                 "with Clopper-Pearson intervals" % (title, completed, total), fontsize=9)
    fig.tight_layout()
    fig.savefig(png_file, dpi=130)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_fragility.py RESULT.h5 OUT.png")
    main(sys.argv[1], sys.argv[2])
