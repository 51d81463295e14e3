#!/usr/bin/python3
"""caskdem.rollout against `caskdem ensemble` on the same realisations, in one run: the benchmark
ensemble's own realisations (caskdem.realisations) through the Python module, and the command
line on the file, alternately, each `--repeats` times; the medians and their ratio, after
checking that both give the same outcomes bit for bit.

The command line's time is its process's wall time (reading the motions, the run, the fragility
analysis and the result file); rollout's is the call's (the ensemble loaded once before, as a
driver that calls it many times would). Loading the ensemble from Python is timed apart.

Run from the repository: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py
  [--ensemble FILE] [--repeats 3] [--threads 2] [--out bench/results/NAME-python.json]
"""

import argparse
import json
import os
import pathlib
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import caskdem

ROOT = pathlib.Path(__file__).resolve().parents[1]


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            return next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        return platform.processor()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ensemble", type=pathlib.Path, default=ROOT / "ensembles/benchmark-1-3-elcentro-20s.toml")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--binary", type=pathlib.Path, default=ROOT / "build/src/caskdem")
    parser.add_argument("--out", type=pathlib.Path)
    arguments = parser.parse_args()

    started = time.perf_counter()
    ensemble = caskdem.load_ensemble(arguments.ensemble)
    columns = caskdem.realisations(ensemble)
    load_s = time.perf_counter() - started

    cli, python = [], []
    with tempfile.TemporaryDirectory() as folder:
        result = pathlib.Path(folder) / "bench.h5"
        for repeat in range(arguments.repeats):
            for which in (("cli", "python") if repeat % 2 == 0 else ("python", "cli")):
                if which == "cli":
                    t = time.perf_counter()
                    subprocess.run([str(arguments.binary), "ensemble", str(arguments.ensemble), "--out", str(result),
                                    "--no-plot", "--quiet", "--threads", str(arguments.threads)], check=True,
                                   stdout=subprocess.DEVNULL)
                    cli.append(time.perf_counter() - t)
                else:
                    t = time.perf_counter()
                    outcome = caskdem.rollout(ensemble, columns, threads=arguments.threads)
                    python.append(time.perf_counter() - t)
            if repeat == 0:
                stored = caskdem.read_result(result)["realisations"]
                for key in ("status", "max_abs_rotation", "max_abs_slide", "residual_slide", "max_uplift", "end_time"):
                    a, b = np.asarray(outcome[key]), np.asarray(stored[key])
                    if a.dtype == np.float64:
                        a, b = a.view(np.uint64), b.view(np.uint64)
                    if not np.array_equal(a, b):
                        sys.exit(f"bench_python.py: rollout and caskdem ensemble differ in {key}")

    report = {
        "machine": cpu_name(),
        "ensemble": str(arguments.ensemble.relative_to(ROOT) if arguments.ensemble.is_relative_to(ROOT)
                        else arguments.ensemble),
        "realisations": int(ensemble.size),
        "threads": arguments.threads,
        "repeats": arguments.repeats,
        "same_outcomes_bit_for_bit": True,
        "command_line_s": cli,
        "rollout_s": python,
        "load_ensemble_s": load_s,
        "command_line_median_s": statistics.median(cli),
        "rollout_median_s": statistics.median(python),
        "rollout_over_command_line": statistics.median(python) / statistics.median(cli),
    }
    print(json.dumps(report, indent=2))
    if arguments.out:
        arguments.out.write_text(json.dumps(report, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
