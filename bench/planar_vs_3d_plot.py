#!/usr/bin/python3
"""The planar and 3D fragility curves side by side, with their bootstrap bands and stripes.

usage: bench/planar_vs_3d_plot.py ROWS.csv CURVES.csv OUT.png TITLE
(ROWS and CURVES from bench/planar_vs_3d; docs/cask3d.md, "Planar against 3D")
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main(rows_file, curves_file, png_file, title):
    rows, curves = read(rows_file), read(curves_file)
    limits = list(dict.fromkeys(r["limit_state"] for r in rows))
    models = list(dict.fromkeys(r["model"] for r in rows))
    colours = dict(zip(models, ["tab:orange", "tab:green", "tab:blue"]))
    fig, axes = plt.subplots(1, len(limits), figsize=(5 * len(limits), 4.2), sharey=True)
    for ax, limit in zip(axes, limits):
        for model in models:
            curve = defaultdict(list)
            for c in curves:
                if c["model"] == model and c["limit_state"] == limit:
                    for key in ("pga_g", "probability", "lower", "upper"):
                        curve[key].append(float(c[key]))
            colour = colours[model]
            if curve:
                ax.plot(curve["pga_g"], curve["probability"], color=colour, lw=1.2, label=model)
                ax.fill_between(curve["pga_g"], curve["lower"], curve["upper"], color=colour, alpha=0.15, lw=0)
            stripes = [r for r in rows if r["model"] == model and r["limit_state"] == limit]
            ax.errorbar([float(r["pga_g"]) for r in stripes], [float(r["probability"]) for r in stripes],
                        yerr=[[float(r["probability"]) - float(r["lower"]) for r in stripes],
                              [float(r["upper"]) - float(r["probability"]) for r in stripes]],
                        fmt="o", ms=3, color=colour, lw=0.6, capsize=2, label=None if curve else model)
        ax.set_title(limit, fontsize=10)
        ax.set_xlabel("PGA [g] (planar: the component's; 3D: the pair's RotD50)")
        ax.grid(True, lw=0.3)
        ax.set_xlim(0.0, 2.1)
    axes[0].set_ylabel("probability of exceedance")
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(png_file, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
