#!/usr/bin/env bash
# The README's second command: install the dependencies, build, and run the test suite.
#
#   scripts/test.sh          the suite (ctest), about 10 minutes on two cores: everything but the
#                            full diagnoses at shipped settings (labels diagnosis-full and
#                            diagnosis-more) and the README's tour run line by line (label tour)
#   scripts/test.sh --full   the full gate, as CI runs it (.ci/run): the suite with the tour and
#                            the full diagnoses of label diagnosis-full, the suite again under
#                            AddressSanitizer and UndefinedBehaviorSanitizer, the ensemble tests
#                            under ThreadSanitizer. About 70 minutes on a two-core AMD EPYC, the
#                            slowest machine CI has run it on (docs/fuzzing.md has the stages); CI
#                            gives it 90. The diagnoses of label diagnosis-more (ctest -L
#                            diagnosis-more, about 33 minutes) and the readers under libFuzzer
#                            (bench/fuzz.sh, docs/fuzzing.md) are run apart.
set -euo pipefail
cd "$(dirname "$0")/.."
full=false
case "${1:-}" in
  "") ;;
  --full) full=true ;;
  *) echo "usage: scripts/test.sh [--full]" >&2; exit 2 ;;
esac
# ctest runs two tests at once on two cores, each with its own OpenMP threads: a thread that
# waits at a barrier sleeps rather than spins on a core the other test needs (two diagnoses side
# by side, two threads each: 37.6 s against 42.6 s; alone the same, 20.6 s against 21.0 s).
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
# Each stage's end and the time so far, so a slow gate shows where its time went.
stage() { echo "== scripts/test.sh: $1 at $((SECONDS / 60)) min $((SECONDS % 60)) s"; }
scripts/install-deps.sh
stage "dependencies installed"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCASKDEM_BUILD_TESTS=ON -DCASKDEM_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build -j"$(nproc)"
stage "Release build done"
if $full; then
  ctest --test-dir build --output-on-failure --no-tests=error -j"$(nproc)" -LE 'gpu|diagnosis-more'
else
  ctest --test-dir build --output-on-failure --no-tests=error -j"$(nproc)" -LE 'gpu|diagnosis-full|diagnosis-more|tour'
fi
# The GPU engine against the CPU, verbose: where no GPU is present each test says why it did not
# run; where one is, the table of every shipped ensemble's realisations (docs/performance.md).
ctest --test-dir build --output-on-failure --no-tests=error -L gpu -V >build/gpu-tests.log 2>&1 ||
  { cat build/gpu-tests.log; exit 1; }
grep -E "Skipped|no GPU|GPU:|identical|\.toml|tests passed|Test #" build/gpu-tests.log || true
stage "suite passed"
$full || exit 0
# The suite again under AddressSanitizer and UndefinedBehaviorSanitizer, and the ensemble tests
# under ThreadSanitizer (scripts/sanitize.sh; docs/fuzzing.md, "Sanitizer builds").
scripts/sanitize.sh address
stage "address and undefined-behaviour sanitizers passed"
scripts/sanitize.sh thread
stage "thread sanitizer passed"
