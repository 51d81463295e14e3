#!/bin/sh
# The diagnosis in a closed loop: each data set is diagnosed with its plan; the laboratory then
# runs the first proposed test (the generator drives the same hidden cask, same seed and noise
# model, with the plan's drive-1.csv) and the set, that test added, is diagnosed again. The data
# come from the independent generator (tests/independent: six tests, the added one test7), or
# with OWN=1 from caskdem synthesize-measured (eight tests, the added one test9). One CSV row per
# data set: the answer before and after, the test proposed and its separation, and the wall time
# of each diagnosis (the first with its plan); bench/closed_loop_table.py makes the rates, before
# and after, with their intervals.
#
#   bench/closed_loop.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED] [EFFECTS]
#
# The added test trains in the second diagnosis; with ADDED=heldout it is held out instead, so that
# the second diagnosis fits the same training tests as the first and judges every candidate on its
# prediction of the test the plan chose (as the first one's fits were made before it was run).
#
# With WARM=1 the second diagnosis starts its searches also from the first's fits (diagnose
# --start-from BEFORE/diagnosis.json), as a laboratory re-diagnosing with the added test would.
#
# Both diagnoses use curvature errors and skip the search for a second effect (it does not change
# the cause); the second skips the plan. Where the first leaves only the baseline standing there
# is no test to propose, and the answer after is the answer before. KEEP=DIR copies each set's
# two diagnosis.json, plan.json and truth.json to DIR/EFFECT-SEED-*. About 4 to 8 minutes per set
# on 2 cores (the own generator's eight tests take longer). Appends to OUT_CSV, so a stopped run resumes.
set -eu
usage="usage: closed_loop.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED] [EFFECTS]"
build=${1:?$usage}
out=${2:?$usage}
seeds=${3:-10}
first=${4:-2001}
effects=${5:-"none velocity_dependent_friction amplitude_dependent_restitution eccentric_mass base_imperfection vertical_excitation floor_compliance out_of_plane_loss sensor_delay"}
caskdem="$build/src/caskdem"
if [ -z "${OWN:-}" ]; then GENERATOR="$build/tests/independent/caskdem_independent_data"; else unset GENERATOR; fi
here=$(dirname "$0")
. "$here/synthetic_sets.sh"

# Test ADDED of the set in DIR (hidden EFFECT, SEED) driven by DRIVE, by the generator that made it.
add_test() {
  dir=$1 effect=$2 seed=$3 drive=$4
  if [ -n "${GENERATOR:-}" ]; then
    "$GENERATOR" --out "$dir" --effect "$effect" --seed "$seed" --drive "$drive" --test 7 >/dev/null
  elif [ "$effect" = none ]; then
    "$caskdem" synthesize-measured --out "$dir" --seed "$seed" --drive "$drive" --test 9 >/dev/null
  else
    "$caskdem" synthesize-measured --out "$dir" --seed "$seed" --effect "$effect" --drive "$drive" --test 9 >/dev/null
  fi
}
[ -s "$out" ] || /usr/bin/python3 "$here/closed_loop_row.py" --header >"$out"

loop_set() {
  dir=$1 effect=$2 seed=$3
  start=$(date +%s)
  "$caskdem" diagnose "$dir" --out "$dir/before" --quiet --no-plot --uncertainty curvature --no-second-effect >/dev/null
  middle=$(date +%s)
  if [ -f "$dir/before/drive-1.csv" ]; then
    add_test "$dir" "$effect" "$seed" "$dir/before/drive-1.csv"
    if [ "${ADDED:-training}" = heldout ]; then  # judge the fits on the added test's prediction: the same training tests
      added=$(ls "$dir" | sed -n 's/^\(test[0-9]*\)\.csv$/\1/p' | sort -V | tail -n 1)
      sed -i "s/^heldout = \[\(.*\)\]$/heldout = [\1, \"$added\"]/" "$dir/specimen.toml"
    fi
    warm=
    [ -z "${WARM:-}" ] || warm="--start-from $dir/before/diagnosis.json"
    # shellcheck disable=SC2086  # $warm is two words or none
    "$caskdem" diagnose "$dir" --out "$dir/after" --quiet --no-plot --uncertainty curvature --no-second-effect \
      --no-plan $warm >/dev/null
  fi
  end=$(date +%s)
  plan="$dir/before/plan.json" after="$dir/after/diagnosis.json"
  [ -f "$plan" ] || plan=-
  [ -f "$after" ] || after=-
  /usr/bin/python3 "$here/closed_loop_row.py" "$effect" "$seed" "$dir/before/diagnosis.json" "$plan" "$after" \
    $((middle - start)) "$([ "$after" = - ] || echo $((end - middle)))" >>"$out"
  if [ -n "${KEEP:-}" ]; then
    mkdir -p "$KEEP"
    cp "$dir/before/diagnosis.json" "$KEEP/$effect-$seed-before.json"
    [ ! -f "$dir/before/plan.json" ] || cp "$dir/before/plan.json" "$KEEP/$effect-$seed-plan.json"
    [ ! -f "$dir/after/diagnosis.json" ] || cp "$dir/after/diagnosis.json" "$KEEP/$effect-$seed-after.json"
    cp "$dir/truth.json" "$KEEP/$effect-$seed-truth.json"
    [ ! -f "$dir/before/drive-1.csv" ] || cp "$dir/before/drive-1.csv" "$KEEP/$effect-$seed-drive-1.csv"
  fi
  tail -n 1 "$out"
}

for_each_new_set "$out" "$seeds" "$first" "$effects" loop_set
