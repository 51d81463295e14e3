#!/bin/sh
# Fuzzing every reader of users' files with libFuzzer (fuzz/, docs/fuzzing.md): builds the
# targets with clang and the address and undefined-behaviour sanitizers into BUILD_DIR, seeds
# each corpus from ../shared/motions, the shipped cases and ensembles, the test data and
# fuzz/seeds, and runs each target for RUNS executions (or SECONDS, whichever ends first) with
# a 1 s limit per input and 2 GB of memory. Per target it prints the executions, the time,
# the coverage and what was found; a finding's input is kept in OUT/findings/ and the run
# goes on to the next target. Exit status 1 when anything was found.
#
#   bench/fuzz.sh [BUILD_DIR] [OUT] [RUNS] [SECONDS] [TARGETS]
#
# Defaults: build-fuzz, fuzz-out, 1000000 runs, 3600 s, every target. TIMEOUT (default 1 s)
# is the limit per input. The CI smoke run (scripts/test.sh) gives each target 10 s, and each
# input 10 s so that a loaded machine does not count a slow input as a finding.
set -eu
cd "$(dirname "$0")/.."
build=${1:-build-fuzz}
out=${2:-fuzz-out}
runs=${3:-1000000}
seconds=${4:-3600}
targets=${5:-"record case ensemble measured_test specimen result_file hazard_curve"}
shared=${CASKDEM_SHARED:-../shared}

compiler=$(command -v clang++-15 || command -v clang++ || true)
[ -n "$compiler" ] || { echo "fuzz.sh: no clang++ (libFuzzer); scripts/install-deps.sh installs it" >&2; exit 2; }
c_compiler=$(echo "$compiler" | sed 's/clang++/clang/')
CC=$c_compiler CXX=$compiler cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASKDEM_BUILD_TESTS=OFF \
  -DCASKDEM_BUILD_BENCHMARKS=OFF -DCASKDEM_BUILD_FUZZERS=ON -DCASKDEM_WITH_MPI=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null

mkdir -p "$out/findings"
seeds="$out/seeds"
rm -rf "$seeds" && mkdir -p "$seeds"
for t in $targets; do mkdir -p "$seeds/$t" "$out/corpus/$t"; done

# Seeds: short valid records (4 header lines, NPTS cut to 64 values), column files, the
# shipped cases and ensembles, the test fixtures and a result file of the small test ensemble.
[ ! -d "$seeds/record" ] || /usr/bin/python3 - "$shared/motions" "$seeds/record" <<'PY'
import pathlib, re, sys
source, target = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
for k, at2 in enumerate(sorted(source.rglob("*.AT2"))[:12]):
    lines = at2.read_text(errors="replace").splitlines()
    values = " ".join(lines[4:20]).split()[:64]
    header = re.sub(r"NPTS\s*=\s*\d+", "NPTS= %d" % len(values), lines[3])
    if header == lines[3]:
        header = re.sub(r"^\s*\d+", "%d" % len(values), lines[3])
    (target / ("seed%02d.AT2" % k)).write_text("\n".join(lines[:3] + [header] + [" ".join(values[i:i + 5]) for i in range(0, len(values), 5)]) + "\n")
(target / "columns.csv").write_text("t, Accel[g]\n" + "".join("%.2f, %.4f\n" % (0.01 * i, 0.1 * ((i * 7) % 5 - 2)) for i in range(40)))
(target / "single.txt").write_text("# acceleration in gal\n" + "".join("%.3f\n" % (3.0 * ((i * 3) % 7 - 3)) for i in range(40)))
PY
[ ! -d "$seeds/case" ] || cp cases/*.toml tests/casefile/data/*.toml "$seeds/case/" 2>/dev/null || true
[ ! -d "$seeds/ensemble" ] || cp ensembles/*.toml tests/ensemble/data/*.toml "$seeds/ensemble/"
[ ! -d "$seeds/measured_test" ] || cp fuzz/data/measured/*.csv "$seeds/measured_test/"
[ ! -d "$seeds/specimen" ] || cp fuzz/seeds/specimen.toml "$seeds/specimen/"
[ ! -d "$seeds/hazard_curve" ] || cp hazard/*.csv hazard/PGA/*.csv "$seeds/hazard_curve/"
if [ -d "$seeds/result_file" ]; then
  "$build/src/caskdem" ensemble tests/ensemble/data/mixed-outcomes.toml --out "$seeds/result_file/mixed.h5" \
    --threads 1 --quiet --no-plot >/dev/null
fi

found=0
printf "%-14s %10s %8s %8s %8s %s\n" target executions seconds cov features findings
for t in $targets; do
  dict=""
  [ ! -f "fuzz/$t.dict" ] || dict="-dict=fuzz/$t.dict"
  log="$out/$t.log"
  start=$(date +%s)
  set +e
  # -fork keeps going after a finding (each one kept in findings/), one worker per core.
  "$build/fuzz/fuzz_$t" $dict -runs="$runs" -max_total_time="$seconds" -timeout="${TIMEOUT:-1}" -rss_limit_mb=2048 \
    -max_len=65536 -fork="$(nproc)" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -artifact_prefix="$out/findings/$t-" "$out/corpus/$t" "$seeds/$t" >"$log" 2>&1
  set -e
  elapsed=$(( $(date +%s) - start ))
  executions=$(grep -o 'exec/s: [0-9]*' "$log" | tail -1 | awk -v s="$elapsed" '{print $2 * s}')
  last=$(grep -E '#[0-9]+' "$log" | tail -1)
  total=$(echo "$last" | grep -o '^#[0-9]*' | tr -d '#')
  cov=$(echo "$last" | grep -o 'cov: [0-9]*' | awk '{print $2}')
  ft=$(echo "$last" | grep -o 'ft: [0-9]*' | awk '{print $2}')
  findings=$(ls "$out/findings" 2>/dev/null | grep -c "^$t-" || true)
  [ "$findings" = 0 ] || found=1
  printf "%-14s %10s %8s %8s %8s %s\n" "$t" "${total:-$executions}" "$elapsed" "${cov:-?}" "${ft:-?}" "$findings"
done
exit $found
