"""Maximum rotation against frequency, DEM against rigid-block theory (the source paper's Fig. 11).

Usage: plot_sweep.py SWEEP.csv OUT.png
"""
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_file, png_file):
    data = np.genfromtxt(csv_file, delimiter=",", names=True)
    fig, ax = plt.subplots(figsize=(8, 5))
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
    for i, amplitude in enumerate(np.unique(data["amplitude_cm"])):
        rows = data[data["amplitude_cm"] == amplitude]
        colour = colours[i % len(colours)]
        dem = np.minimum(rows["dem_rotation_ratio"], 1.2)
        theory = np.minimum(rows["theory_rotation_ratio"], 1.2)
        ax.plot(rows["frequency_Hz"], dem, "o-", color=colour, ms=4, label="DEM, %.1f cm" % amplitude)
        ax.plot(rows["frequency_Hz"], theory, "--", color=colour, label="theory, %.1f cm" % amplitude)
        tipped = rows["dem_tipped"] > 0
        ax.plot(rows["frequency_Hz"][tipped], dem[tipped], "x", color="k", ms=7)
    ax.axhline(1.0, color="gray", lw=0.8)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel(r"max $|\theta| / \alpha$ (tipped shown at 1.2, x)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(png_file, dpi=130)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_sweep.py SWEEP.csv OUT.png")
    main(sys.argv[1], sys.argv[2])
