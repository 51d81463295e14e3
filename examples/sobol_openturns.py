#!/usr/bin/python3
"""What drives the tip-over of the 1/3 model cask? First-order and total Sobol indices, with
their 95 % intervals, from OpenTURNS (Debian's python3-openturns) driving caskdem.rollout.

Inputs (independent): static friction U(0.5, 0.7) (the kinetic coefficient kept at 3/4 of it,
the nominal ratio), rocking restitution U(0.94, 0.97), eccentricity of the centre of mass
U(0, 3 cm), and the record, one of the ensemble's 8 built-in synthetic earthquakes with equal
probability. The cask and the records are the shipped ensemble's (ensembles/model-1-3-builtin.toml):
a 1/3 scale model under prototype motions compressed by the similarity law, so intensities are
the model's table PGV (a prototype's PGV is sqrt(3) times larger).

Outputs, both from one batch of realisations (each design point at every level of a PGV grid):
  * tipped at 50 cm/s: whether the cask tips over at one intensity (its mean is the tip-over
    probability there; its indices split that probability's variance among the inputs);
  * ln capacity: the log of the lowest grid PGV that tips the cask (an incremental dynamic
    analysis). Its mean is the log of the fragility median and its variance the fragility's
    beta^2; a parameter's first-order index is the share of that variance that the median
    moves by when the parameter alone changes.

Indices by Saltelli's design (N (d + 2) points) and Martinez's estimators, bootstrap intervals.
Run: /usr/bin/python3 examples/sobol_openturns.py [--base-size N] [--out DIR]
"""

import argparse
import pathlib
import sys
import time

import numpy as np
import openturns as ot

import caskdem

HERE = pathlib.Path(__file__).resolve().parent
INPUTS = ["friction", "restitution", "eccentricity", "record"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base-size", type=int, default=512, help="N of Saltelli's design (default 512)")
    parser.add_argument("--levels", type=int, default=12, help="PGV levels of the capacity grid (default 12)")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("results/sobol"), help="folder for the table")
    arguments = parser.parse_args()
    started = time.monotonic()

    ensemble = caskdem.load_ensemble(HERE.parent / "ensembles/model-1-3-builtin.toml")
    records = len(ensemble.motion_names)
    ot.RandomGenerator.SetSeed(20261127)
    inputs = ot.ComposedDistribution([ot.Uniform(0.5, 0.7), ot.Uniform(0.94, 0.97), ot.Uniform(0.0, 0.03),
                                      ot.Uniform(0.0, float(records))])
    inputs.setDescription(INPUTS)
    design = np.array(ot.SobolIndicesExperiment(inputs, arguments.base_size, False).generate())
    points = len(design)

    # Every design point at every level: one rollout of points x levels realisations.
    cm_per_s = 0.01
    levels = np.geomspace(10.0, 150.0, arguments.levels) * cm_per_s
    probe = 50.0 * cm_per_s
    levels = np.sort(np.append(levels, probe))
    rows = np.repeat(design, len(levels), axis=0)
    level = np.tile(levels, points)
    friction = rows[:, 0]
    outcome = caskdem.rollout(ensemble, motion=np.minimum(np.floor(rows[:, 3]), records - 1).astype(int), level=level,
                              friction_static=friction, friction_kinetic=0.75 * friction, restitution=rows[:, 1],
                              eccentricity=rows[:, 2])
    tipped = outcome["tipped_over"].reshape(points, len(levels))

    at_probe = tipped[:, np.searchsorted(levels, probe)].astype(float)
    first = np.where(tipped.any(axis=1), tipped.argmax(axis=1), len(levels))
    # The capacity lies between the last level that stood and the first that tipped: their
    # geometric mean; a cask standing at every level is censored one grid step above the grid.
    step = levels[1] / levels[0]
    upper = np.where(first < len(levels), levels[np.minimum(first, len(levels) - 1)], levels[-1] * step)
    lower = np.where(first > 0, upper / step, levels[0] / step)
    ln_capacity = 0.5 * (np.log(lower) + np.log(upper))
    censored = int(np.sum(first == len(levels)))

    print(f"caskdem {caskdem.__version__}, OpenTURNS {ot.__version__}: {points} design points x {len(levels)} PGV "
          f"levels = {len(level)} realisations of the 1/3 model (model-scale table PGV)")
    print(f"tip-over probability at 50 cm/s: {at_probe.mean():.3f}; fragility median "
          f"{np.exp(ln_capacity.mean()) / cm_per_s:.1f} cm/s (full size x sqrt(3): "
          f"{np.sqrt(3.0) * np.exp(ln_capacity.mean()) / cm_per_s:.1f} cm/s), beta {ln_capacity.std():.2f}; "
          f"{censored} points stood at every level (capacity censored)")
    table = []
    failures = []
    for name, output in (("tipped at 50 cm/s", at_probe), ("ln capacity", ln_capacity)):
        algorithm = ot.MartinezSensitivityAlgorithm(ot.Sample(design), ot.Sample(output[:, None]), arguments.base_size)
        algorithm.setBootstrapSize(300)
        algorithm.setConfidenceLevel(0.95)
        first_order, total = algorithm.getFirstOrderIndices(), algorithm.getTotalOrderIndices()
        first_interval = algorithm.getFirstOrderIndicesInterval()
        total_interval = algorithm.getTotalOrderIndicesInterval()
        print(f"\n{name}: variance {output.var():.4g}")
        print(f"  {'input':<13}{'first order':>12}  {'95 % interval':>17}{'total':>10}  {'95 % interval':>17}")
        for i, input_name in enumerate(INPUTS):
            s1, st = first_order[i], total[i]
            l1, u1 = first_interval.getLowerBound()[i], first_interval.getUpperBound()[i]
            lt, ut = total_interval.getLowerBound()[i], total_interval.getUpperBound()[i]
            print(f"  {input_name:<13}{s1:>12.3f}  [{l1:>6.3f}, {u1:>6.3f}]{st:>10.3f}  [{lt:>6.3f}, {ut:>6.3f}]")
            table.append((name, input_name, s1, l1, u1, st, lt, ut))
            # First order cannot exceed total: a violation beyond both intervals is an error.
            if l1 > ut:
                failures.append(f"{name}, {input_name}: first order {s1:.3f} above total {st:.3f} beyond the intervals")
        sums = (sum(first_order), sum(total))
        print(f"  {'sum':<13}{sums[0]:>12.3f}  {'':>17}{sums[1]:>10.3f}")
        # The first-order indices sum to at most 1 and the total ones to at least 1 (interactions
        # count in each total they involve), within the estimators' noise.
        if sum(first_interval.getLowerBound()) > 1.0 or sum(total_interval.getUpperBound()) < 1.0:
            failures.append(f"{name}: sums {sums[0]:.3f} (first) and {sums[1]:.3f} (total) do not bracket 1")

    arguments.out.mkdir(parents=True, exist_ok=True)
    with open(arguments.out / "sobol-indices.csv", "w") as f:
        f.write("output,input,first_order,first_lower,first_upper,total,total_lower,total_upper\n")
        for row in table:
            f.write(",".join([row[0], row[1]] + [f"{v:.6g}" for v in row[2:]]) + "\n")
    print(f"\nwrote {arguments.out / 'sobol-indices.csv'} in {time.monotonic() - started:.0f} s")
    if failures:
        print("\n".join(failures), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
