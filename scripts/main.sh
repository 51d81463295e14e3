#!/usr/bin/env bash
# The README's first command: install the dependencies, build, and run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCASKDEM_BUILD_TESTS=OFF -DCASKDEM_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build -j"$(nproc)" --target caskdem _caskdem
# caskdem on the PATH, as the README's tour writes it: a link in /usr/local/bin (as root), or in
# ~/.local/bin (which Debian's shells put on the PATH at login when it exists).
bin=/usr/local/bin
if [ ! -w "$bin" ]; then
  bin="$HOME/.local/bin"
  mkdir -p "$bin"
fi
ln -sf "$PWD/build/src/caskdem" "$bin/caskdem"
case ":$PATH:" in
  *":$bin:"*) echo "main.sh: caskdem is $bin/caskdem (a link to build/src/caskdem)" ;;
  *) echo "main.sh: caskdem is $bin/caskdem (a link to build/src/caskdem); $bin is not on this shell's PATH yet" ;;
esac
# The Python module (docs/python.md) for Debian's interpreter: a .pth file in its site folder
# (/usr/local/lib/python3.X/dist-packages as root, the user's site folder otherwise) that puts
# build/python on its path.
if [ "$(id -u)" -eq 0 ]; then
  site=$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')
else
  site=$(/usr/bin/python3 -c 'import site; print(site.getusersitepackages())')
fi
mkdir -p "$site"
echo "$PWD/build/python" >"$site/caskdem.pth"
echo "main.sh: import caskdem works in /usr/bin/python3 ($site/caskdem.pth names $PWD/build/python)"
# A fragility analysis on built-in synthetic earthquakes (no downloaded file): results/*.h5 and *.png,
# with the fragility table beside it (*-fragility.csv and .json), then the annual frequency of each
# limit state at a synthetic site, the 1/3 model's curves taken to the full-size cask's by the
# similarity law (the result file records the model's scale): results/*-risk.json and *-risk.png
build/src/caskdem ensemble ensembles/model-1-3-builtin.toml --out results/model-1-3-builtin.h5
build/src/caskdem risk results/model-1-3-builtin.h5 --hazard hazard/example-site-pgv.csv
