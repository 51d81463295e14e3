#!/usr/bin/env bash
# The README's first command: install the dependencies, build, and run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCASKDEM_BUILD_TESTS=OFF -DCASKDEM_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build -j"$(nproc)" --target caskdem
# A fragility analysis on built-in synthetic earthquakes (no downloaded file): results/*.h5 and *.png,
# then the annual frequency of each limit state at a synthetic site, the 1/3 model's curves taken
# to the prototype's PGV by the similarity law: results/*-risk.json and *-risk.png
build/src/caskdem ensemble ensembles/model-1-3-builtin.toml --out results/model-1-3-builtin.h5
build/src/caskdem risk results/model-1-3-builtin.h5 --hazard hazard/example-site-pgv.csv --similarity 3
