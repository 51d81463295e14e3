"""Plot of one 3D caskdem run: tilt, the base centre's walk and the slip (sliding over the floor
where the cask bears, rolling excluded) and the table's three components against time, and the
top of the axis seen from above.

Usage: plot_run3d.py RUN.h5 OUT.png
Reads the layout written by `caskdem run` for a 3D case (docs/output.md, "A 3D run").
"""
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def main(run_file, png_file):
    with h5py.File(run_file, "r") as f:
        history = f["history"]
        t = history["time"][:]
        tilt = history["tilt"][:]
        azimuth = history["tilt_azimuth"][:]
        slide_x = history["slide_x"][:]
        slide_z = history["slide_z"][:]
        table_x = history["table_x"][:]
        table_z = history["table_z"][:]
        table_vertical = history["table_vertical"][:]
        slip = np.hypot(history["slip_x"][:], history["slip_z"][:]) if "slip_x" in history else None
        summary = {key: value for key, value in f["summary"].attrs.items()}
        height = float(f["model"].attrs["height_m"])
        alpha = float(summary["stability_angle_rad"])
        title = text(f.attrs.get("title", ""))
        status = text(summary["status"])

    fig = plt.figure(figsize=(12, 7.5))
    grid = fig.add_gridspec(3, 2, width_ratios=[1.6, 1.0])
    ax_tilt = fig.add_subplot(grid[0, 0])
    ax_slide = fig.add_subplot(grid[1, 0], sharex=ax_tilt)
    ax_table = fig.add_subplot(grid[2, 0], sharex=ax_tilt)
    ax_top = fig.add_subplot(grid[:, 1])

    ax_tilt.plot(t, tilt / alpha, lw=0.8, color="tab:blue")
    ax_tilt.axhline(1.0, color="tab:red", ls="--", lw=0.8)
    ax_tilt.set_ylabel(r"tilt / $\alpha$")
    ax_tilt.text(0.01, 0.9, r"$\alpha$ = %.3f rad (dashed)" % alpha, transform=ax_tilt.transAxes, fontsize=8)
    ax_slide.plot(t, 100.0 * slide_x, lw=0.8, label="base walk x")
    ax_slide.plot(t, 100.0 * slide_z, lw=0.8, label="base walk z")
    ax_slide.plot(t, 100.0 * np.hypot(slide_x, slide_z), lw=0.8, color="k",
                  label="|base walk| (sliding and rolling)")
    if slip is not None:
        ax_slide.plot(t, 100.0 * slip, lw=1.2, color="tab:red", label="|slip| (sliding alone)")
    ax_slide.set_ylabel("[cm]")
    ax_slide.legend(fontsize=7, loc="upper left")
    ax_table.plot(t, 100.0 * table_x, lw=0.5, label="x")
    ax_table.plot(t, 100.0 * table_z, lw=0.5, label="z")
    ax_table.plot(t, 100.0 * table_vertical, lw=0.5, label="vertical")
    ax_table.set_ylabel("table acc. [gal]")
    ax_table.set_xlabel("time [s]")
    ax_table.legend(fontsize=7, loc="upper left")
    for ax in (ax_tilt, ax_slide, ax_table):
        ax.grid(True, lw=0.3)

    # The top of the axis from above: the base centre's sliding plus H sin(tilt) towards the lean.
    top_x = slide_x + height * np.sin(tilt) * np.cos(azimuth)
    top_z = slide_z + height * np.sin(tilt) * np.sin(azimuth)
    ax_top.plot(100.0 * top_x, 100.0 * top_z, lw=0.6, color="tab:purple")
    # Framed on the trace; the circle where the tilt reaches alpha is drawn when it is in view.
    reach = height * np.sin(alpha)
    extent = max(1.25 * float(np.max(np.hypot(top_x, top_z))), 0.01)
    ax_top.set_xlim(-100.0 * extent, 100.0 * extent)
    ax_top.set_ylim(-100.0 * extent, 100.0 * extent)
    ax_top.set_aspect("equal")
    if reach < 1.4 * extent:
        circle = np.linspace(0.0, 2.0 * np.pi, 361)
        ax_top.plot(100.0 * reach * np.cos(circle), 100.0 * reach * np.sin(circle), color="tab:red", ls="--", lw=0.8)
        ax_top.set_title(r"top of the axis from above (dashed: tilt $\alpha$)", fontsize=9)
    else:
        ax_top.set_title(r"top of the axis from above (tilt $\alpha$ at %.0f cm)" % (100.0 * reach), fontsize=9)
    ax_top.set_xlabel("x [cm]")
    ax_top.set_ylabel("z [cm]")
    ax_top.grid(True, lw=0.3)

    fig.suptitle("%s: %s, max tilt %.3f alpha" % (title, status, float(summary["max_tilt_ratio"])))
    fig.tight_layout()
    fig.savefig(png_file, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
