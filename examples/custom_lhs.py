#!/usr/bin/python3
"""A sampling plan of your own through caskdem.rollout: a Latin hypercube over static friction
and rocking restitution, drawn with numpy, run at stripes of table PGV on the shipped ensemble's
eight built-in synthetic earthquakes; the tip-over fragility fitted with the ensemble's own
estimator, band and fit test (caskdem.fit_fragility), and plotted.

The 1/3 model cask under prototype motions compressed by the similarity law: every PGV here is
the model's table PGV; a full-size cask's is sqrt(3) times larger.
Run: /usr/bin/python3 examples/custom_lhs.py [--per-stripe N] [--out DIR]
"""

import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import caskdem  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent


def latin_hypercube(rng, rows, dimensions):
    """One point in each of `rows` equal strata of every dimension, strata paired at random."""
    strata = np.argsort(rng.random((dimensions, rows)), axis=1).T
    return (strata + rng.random((rows, dimensions))) / rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--per-stripe", type=int, default=64, help="realisations per PGV stripe (default 64)")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("results/custom-lhs"))
    arguments = parser.parse_args()

    ensemble = caskdem.load_ensemble(HERE.parent / "ensembles/model-1-3-builtin.toml")
    records = len(ensemble.motion_names)
    cm_per_s = 0.01
    stripes = np.array([20.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0]) * cm_per_s
    n = arguments.per_stripe
    rng = np.random.default_rng(7)
    u = np.vstack([latin_hypercube(rng, n, 2) for _ in stripes])  # a hypercube per stripe
    friction = 0.5 + 0.2 * u[:, 0]         # U(0.5, 0.7)
    restitution = 0.94 + 0.03 * u[:, 1]    # U(0.94, 0.97)
    level = np.repeat(stripes, n)
    motion = np.tile(np.arange(n) % records, len(stripes))  # the records share each stripe equally

    outcome = caskdem.rollout(ensemble, motion=motion, level=level, friction_static=friction,
                              friction_kinetic=0.75 * friction, restitution=restitution)
    counted = outcome["status"] != 4  # a non-finite run counts in no limit state
    fit = caskdem.fit_fragility(level[counted], outcome["tipped_over"][counted], motion[counted])
    if not fit["fitted"]:
        print(f"no fragility curve: {fit['reason']}")
        return 1
    print(f"{len(level)} realisations, {len(stripes)} stripes of {n} (model-scale table PGV)")
    print(f"tip-over fragility: median {fit['median'] / cm_per_s:.1f} cm/s, beta {fit['beta']:.3f}; "
          f"{fit['test']['text']}")
    for s, trials, count, lo, hi in zip(fit["stripes"]["level"], fit["stripes"]["trials"], fit["stripes"]["count"],
                                        fit["stripes"]["lower"], fit["stripes"]["upper"]):
        print(f"  {s / cm_per_s:5.0f} cm/s  {count:3d} of {trials:3d} tipped  [{lo:.2f}, {hi:.2f}]")

    arguments.out.mkdir(parents=True, exist_ok=True)
    figure, axes = plt.subplots(figsize=(7, 4.5))
    band = fit["band"]
    axes.fill_between(band["intensity"] / cm_per_s, band["lower"], band["upper"], alpha=0.25,
                      label=f"{int(100 * fit['confidence'])} % band (records resampled)")
    x = band["intensity"]
    from math import erf, log, sqrt
    curve = [0.5 * (1 + erf(log(v / fit["median"]) / fit["beta"] / sqrt(2))) for v in x]
    axes.plot(x / cm_per_s, curve, "--" if fit["rejected"] else "-",
              label=f"lognormal fit, median {fit['median'] / cm_per_s:.0f} cm/s, beta {fit['beta']:.2f}"
              + (" (REJECTED)" if fit["rejected"] else ""))
    st = fit["stripes"]
    axes.errorbar(st["level"] / cm_per_s, st["probability"], yerr=[st["probability"] - st["lower"],
                  st["upper"] - st["probability"]], fmt="o", capsize=3, label="stripes (95 % Clopper-Pearson)")
    axes.set_xlabel("table PGV of the 1/3 model [cm/s] (model scale)")
    axes.set_ylabel("probability of tipping over")
    axes.set_title("1/3 model cask: tip-over fragility from a custom Latin hypercube")
    axes.set_ylim(-0.02, 1.02)
    axes.legend(loc="upper left", fontsize=8)
    figure.tight_layout()
    figure.savefig(arguments.out / "fragility.png", dpi=120)
    print(f"wrote {arguments.out / 'fragility.png'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
