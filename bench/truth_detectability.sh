#!/bin/sh
# Could the diagnosis have named the hidden mechanism at all? For each synthetic data set of
# bench/diagnosis_success.sh (same generator, same seeds), the hidden model at its true values
# is judged as the diagnosis judges a fit (`caskdem evaluate-measured`), against the baseline
# calibrated on the same data (`caskdem calibrate-measured`): its held-out gain, its BIC delta
# and on how many held-out tests it is better. Where the truth itself is not significant, the
# data, judged by this yardstick at the true values, do not show the effect beyond noise (a fit
# may still pass there, by matching what the truth cannot). Where it is, a miss is the search's
# or the objective's (a lower training J elsewhere). bench/detectability_table.py sets these
# rows beside the diagnoses' answers.
#
#   bench/truth_detectability.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED] [EFFECTS]
#
# The baseline here is calibrate-measured's fit. diagnose may refit it from the candidates'
# baseline parameters and keep the refit when its J is lower, which can only raise the truth's
# BIC delta: a truth that is not significant here is not significant in the diagnosis either.
# About 3 s per data set on 2 cores. Appends to OUT_CSV, so a stopped run resumes.
set -eu
usage="usage: truth_detectability.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED] [EFFECTS]"
build=${1:?$usage}
out=${2:?$usage}
seeds=${3:-20}
first=${4:-1001}
effects=${5:-"velocity_dependent_friction amplitude_dependent_restitution eccentric_mass base_imperfection vertical_excitation floor_compliance out_of_plane_loss sensor_delay"}
caskdem="$build/src/caskdem"
. "$(dirname "$0")/synthetic_sets.sh"
[ -s "$out" ] || echo "hidden,seed,baseline_objective,truth_objective,baseline_heldout_error,truth_heldout_error,truth_gain,truth_bic_delta,heldout_tests_improved,heldout_tests,truth_significant,truth_worst_test,truth_worst_loss,baseline_loss_there" >"$out"

# One data set: the baseline calibrated, then it and the truth judged alike.
judge_truth() {
  dir=$1 effect=$2 seed=$3
  "$caskdem" calibrate-measured "$dir" --out "$dir/calibration" --quiet --uncertainty curvature >/dev/null
  "$caskdem" evaluate-measured "$dir" --from "$dir/calibration/calibration.json" --json "$dir/baseline.json" >/dev/null
  "$caskdem" evaluate-measured "$dir" --model "$effect" --from "$dir/truth.json" --json "$dir/truth-evaluation.json" >/dev/null
  /usr/bin/python3 "$(dirname "$0")/truth_row.py" "$dir/baseline.json" "$dir/truth-evaluation.json" "$effect" "$seed" >>"$out"
  tail -n 1 "$out"
}

for_each_new_set "$out" "$seeds" "$first" "$effects" judge_truth
