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
# The python3 first on the PATH may be another interpreter (pyenv, a virtual environment): of the
# same Python version it can load the module too, and gets the same .pth file in its own site folder.
other=$(command -v python3 || true)
version() { "$1" -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null || true; }
if [ -n "$other" ] && [ "$("$other" -c 'import sys; print(sys.executable)' 2>/dev/null)" != /usr/bin/python3 ]; then
  if [ "$(version "$other")" = "$(version /usr/bin/python3)" ]; then
    other_site=$("$other" -c 'import os, site; d = site.getsitepackages()[0]; print(d if os.access(d, os.W_OK) else site.getusersitepackages())')
    mkdir -p "$other_site"
    echo "$PWD/build/python" >"$other_site/caskdem.pth"
    echo "main.sh: and in $other ($other_site/caskdem.pth; its arrays need numpy in that interpreter)"
  else
    echo "main.sh: python3 on this PATH is $other (Python $(version "$other")); the module is for /usr/bin/python3 (Python $(version /usr/bin/python3))"
  fi
fi
# A fragility analysis on built-in synthetic earthquakes (no downloaded file): results/*.h5 and *.png,
# with the fragility table beside it (*-fragility.csv and .json), then the annual frequency of each
# limit state at a synthetic site, the 1/3 model's curves taken to the full-size cask's by the
# similarity law (the result file records the model's scale): results/*-risk.json and *-risk.png
build/src/caskdem ensemble ensembles/model-1-3-builtin.toml --out results/model-1-3-builtin.h5
build/src/caskdem risk results/model-1-3-builtin.h5 --hazard hazard/example-site-pgv.csv
