"""Predicted histories of the tests caskdem proposes (plan-test): for each of the best-ranked
tests, the table acceleration and every candidate's predicted rotation and sliding (model
scale), so that an experimenter sees where the candidates part.

Usage: plot_plan.py PLAN_HISTORIES.h5 OUT.png
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def main(h5_file, out):
    with h5py.File(h5_file, "r") as f:
        candidates = text(f.attrs["candidates"]).split(",")
        ranks = sorted(f.keys())
        fig, axes = plt.subplots(len(ranks), 3, figsize=(15, 2.8 * len(ranks)), squeeze=False)
        for row, rank in enumerate(ranks):
            g = f[rank]
            t = g["time"][:]
            title = "%s: %s (separation %.3g)" % (rank, text(g.attrs["description"]), float(g.attrs["separation"]))
            ax = axes[row][0]
            ax.plot(t, g["table_acceleration"][:], color="k", lw=0.6)
            ax.set_ylabel("table acceleration [m/s^2]")
            ax.set_title(title, fontsize=8, loc="left")
            for column, (quantity, scale, unit) in enumerate([("rotation", 1.0, "rad"), ("slide", 1000.0, "mm")], 1):
                ax = axes[row][column]
                for c in candidates:
                    ax.plot(t, scale * g[c + "_" + quantity][:], lw=0.8, label=c)
                ax.set_ylabel("predicted %s [%s]" % (quantity, unit))
                if row == 0 and column == 1:
                    ax.legend(fontsize=7)
            for ax in axes[row]:
                ax.grid(True, lw=0.3)
                ax.set_xlabel("time [s], model scale")
        fig.suptitle("Proposed tests: each candidate's prediction at its fitted values", fontsize=10)
        fig.tight_layout()
        fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_plan.py PLAN_HISTORIES.h5 OUT.png")
    main(sys.argv[1], sys.argv[2])
