"""Time-history plot of one caskdem run: rotation, sliding and table acceleration.

Usage: plot_run.py RUN.h5 OUT.png
Reads the layout written by `caskdem run` (docs/output.md).
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(run_file, png_file):
    with h5py.File(run_file, "r") as f:
        history = f["history"]
        t = history["time"][:]
        rotation = history["rotation"][:]
        slide = history["slide"][:]
        table = history["table_acceleration"][:]
        summary = {key: value for key, value in f["summary"].attrs.items()}
        alpha = float(summary["stability_angle_rad"])
        title = f.attrs.get("title", "")
        status = summary["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)

    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(9, 7.5))
    axes[0].plot(t, rotation, lw=0.8, color="tab:blue")
    for sign in (1, -1):
        axes[0].axhline(sign * alpha, color="tab:red", ls="--", lw=0.8)
    axes[0].set_ylabel("rotation [rad]")
    axes[0].text(0.01, 0.92, r"$\pm\alpha$ = %.3f rad (dashed)" % alpha, transform=axes[0].transAxes, fontsize=8)
    axes[1].plot(t, 100.0 * slide, lw=0.8, color="tab:green")
    axes[1].set_ylabel("sliding [cm]")
    axes[2].plot(t, 100.0 * table, lw=0.6, color="tab:gray")
    axes[2].set_ylabel("table acc. [gal]")
    axes[2].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(True, lw=0.3)
    fig.suptitle("%s\nmax |theta|/alpha = %.3f, max sliding %.2f cm, %s"
                 % (title, float(summary["max_rotation_ratio"]), 100.0 * float(summary["max_abs_slide_m"]), status),
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(png_file, dpi=130)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_run.py RUN.h5 OUT.png")
    main(sys.argv[1], sys.argv[2])
