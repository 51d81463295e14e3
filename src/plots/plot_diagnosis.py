"""Plots of a caskdem diagnosis: measured against baseline and extended histories, the
baseline's residual structure, and the ranking of mechanisms by held-out gain.

Usage: plot_diagnosis.py HISTORIES.h5 DIAGNOSIS.json OUT_DIRECTORY
"""
import json
import math
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def histories(h5_file, diagnosis, out):
    with h5py.File(h5_file, "r") as f:
        extended = text(f.attrs.get("extended_model", ""))
        names = sorted(f.keys(), key=lambda n: (len(n), n))
        fig, axes = plt.subplots(len(names), 2, figsize=(12, 2.3 * len(names)), squeeze=False)
        for row, name in enumerate(names):
            g = f[name]
            t = g["time"][:]
            held = " (held out)" if int(g.attrs["heldout"]) else ""
            for column, (quantity, scale, unit) in enumerate([("rotation", 1.0, "rad"), ("slide", 100.0, "cm")]):
                ax = axes[row][column]
                ax.plot(t, scale * g["measured_" + quantity][:], color="k", lw=0.7, label="measured")
                ax.plot(t, scale * g["baseline_" + quantity][:], color="tab:blue", lw=0.8, label="baseline")
                if "extended_" + quantity in g:
                    ax.plot(t, scale * g["extended_" + quantity][:], color="tab:red", lw=0.8, ls="--",
                            label=extended)
                ax.set_ylabel("%s [%s]" % (quantity, unit))
                ax.set_title(name + held, fontsize=9, loc="left")
                ax.grid(True, lw=0.3)
        axes[0][0].legend(fontsize=7)
        for ax in axes[-1]:
            ax.set_xlabel("time [s]")
    fig.suptitle("cause: %s" % diagnosis["cause"], fontsize=11)
    fig.tight_layout()
    fig.savefig(out + "/histories.png", dpi=110)
    plt.close(fig)


def residuals(diagnosis, out):
    measures = diagnosis["measures"]
    tests = sorted(diagnosis["baseline_residuals"].keys(), key=lambda n: (len(n), n))
    matrix = np.array([diagnosis["baseline_residuals"][t] for t in tests])
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 4.5), gridspec_kw={"width_ratios": [3, 2]})
    limit = max(1.0, float(np.max(np.abs(matrix))))
    image = left.imshow(matrix, cmap="RdBu_r", vmin=-limit, vmax=limit, aspect="auto")
    left.set_xticks(range(len(measures)))
    left.set_xticklabels(measures, rotation=40, ha="right", fontsize=8)
    left.set_yticks(range(len(tests)))
    left.set_yticklabels(tests, fontsize=8)
    left.set_title("baseline residuals (simulated - measured) / tolerance", fontsize=9)
    fig.colorbar(image, ax=left)
    rows = diagnosis.get("residual_structure", [])
    labels = ["%s vs %s" % (r["residual"], r["variable"].split(" (")[0]) for r in rows]
    values = [r["statistic"] for r in rows]
    colours = ["tab:red" if abs(v) > (0.7 if r["statistic_name"] == "correlation" else 2.0) else "tab:gray"
               for v, r in zip(values, rows)]
    right.barh(range(len(rows)), values, color=colours)
    right.set_yticks(range(len(rows)))
    right.set_yticklabels(labels, fontsize=7)
    right.axvline(0.0, color="k", lw=0.5)
    right.set_title("residual structure (red: strong pattern)", fontsize=9)
    fig.tight_layout()
    fig.savefig(out + "/residuals.png", dpi=110)
    plt.close(fig)


def ranking(diagnosis, out):
    entries = diagnosis["ranking"]
    names = [e["mechanism"] for e in entries]
    gains = [e["heldout_gain"] for e in entries]
    colours = ["tab:red" if e["significant"] else "tab:gray" for e in entries]
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.barh(range(len(names)), gains, color=colours)
    ax.set_yticks(range(len(names)))
    ax.set_yticklabels(names, fontsize=8)
    ax.invert_yaxis()
    ax.axvline(0.0, color="k", lw=0.5)
    ax.set_xlabel("held-out gain (fractional reduction of held-out error); red: significant")
    ax.set_title("cause: %s" % diagnosis["cause"], fontsize=10)
    fig.tight_layout()
    fig.savefig(out + "/ranking.png", dpi=110)
    plt.close(fig)


def main(h5_file, json_file, out):
    with open(json_file) as f:
        diagnosis = json.load(f)
    histories(h5_file, diagnosis, out)
    residuals(diagnosis, out)
    ranking(diagnosis, out)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit("usage: plot_diagnosis.py HISTORIES.h5 DIAGNOSIS.json OUT_DIRECTORY")
    main(sys.argv[1], sys.argv[2], sys.argv[3])
