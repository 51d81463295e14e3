#!/bin/sh
# Success and false-alarm rates of `caskdem diagnose` on synthetic measured data: for each
# mechanism (and for none), SEEDS data sets from `caskdem synthesize-measured`, each diagnosed
# from the data alone. One CSV row per data set, then the rates per hidden effect
# (bench/success_table.py makes the table of them in docs/diagnosis-accuracy.md, intervals included).
#
#   bench/diagnosis_success.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED] [EFFECTS] [INPUTS] [UNCERTAINTY]
#
# INPUTS sets [diagnosis] input_realisations (default 1: the measured table channel alone);
# write each setting's rows to a CSV of its own. UNCERTAINTY is diagnose's --uncertainty
# (default curvature; jackknife makes the baseline's and the cause's standard errors the
# larger of the jackknife's and the curvature's, at two fits per training test more).
#
# Beside OUT_CSV, OUT_CSV less .csv plus -parameters.csv gets one row per fitted parameter of
# the hidden model (the baseline for none): the true value from the generator's truth.json, the
# fitted value and its standard error, to check the reported uncertainties against the truth
# (bench/parameter_coverage.py).
#
# GENERATOR=PATH takes the data from the independent generator (tests/independent) instead of
# caskdem's own model. The search for a second effect is skipped (it does not change the
# cause); SECOND_EFFECT= (empty) runs it. The proposed tests (plan-test) are skipped too: they
# do not change the cause either.
#
# DIAGNOSE_OPTIONS="..." adds options to each diagnose (such as --refit-from-profile).
#
# KEEP=DIR copies each set's diagnosis.json and truth.json to DIR/EFFECT-SEED-*.json, so that
# decision rules (thresholds, the held-out tolerance rule) can be compared on the same fits
# afterwards (bench/decision_rules.py) without diagnosing again.
#
# The seeds here start at 1001 so they are not the ones the CI tests use (101..110). About
# 1 to 5 minutes per data set on 2 cores. Appends to OUT_CSV, so a stopped run resumes.
set -eu
build=${1:?usage: diagnosis_success.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED] [EFFECTS] [INPUTS] [UNCERTAINTY]}
out=${2:?usage: diagnosis_success.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED] [EFFECTS] [INPUTS] [UNCERTAINTY]}
seeds=${3:-20}
first=${4:-1001}
effects=${5:-"none velocity_dependent_friction amplitude_dependent_restitution eccentric_mass base_imperfection vertical_excitation floor_compliance out_of_plane_loss sensor_delay"}
inputs=${6:-1}
uncertainty=${7:-curvature}
caskdem="$build/src/caskdem"
. "$(dirname "$0")/synthetic_sets.sh"
parameters_out="${out%.csv}-parameters.csv"
[ -s "$out" ] || echo "hidden,seed,cause,second_cause,hidden_gain,hidden_bic_delta,hidden_significant,top,top_gain,wall_s,footprint,adequate,p_value" >"$out"
[ -s "$parameters_out" ] || echo "hidden,seed,model,parameter,truth,fitted,standard_error,at_search_bound,training_objective,training_residuals" >"$parameters_out"

# One data set: diagnosed, its row and its hidden model's parameter rows.
diagnose_set() {
  dir=$1 effect=$2 seed=$3
  # The generator's specimen.toml ends with its [diagnosis] table.
  [ "$inputs" = 1 ] || echo "input_realisations = $inputs" >>"$dir/specimen.toml"
  "$caskdem" diagnose "$dir" --out "$dir/diagnosis" --quiet --no-plot --uncertainty "$uncertainty" --no-plan ${SECOND_EFFECT:---no-second-effect} ${DIAGNOSE_OPTIONS:-} >/dev/null
  /usr/bin/python3 - "$dir/diagnosis/diagnosis.json" "$effect" "$seed" >>"$out" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
effect, seed = sys.argv[2], sys.argv[3]
rank = d["ranking"]
hidden = next((r for r in rank if r["mechanism"] == effect), None)
top = rank[0]
fields = [effect, seed, d["cause"], d["second_cause"] or "",
          "%.4f" % hidden["heldout_gain"] if hidden else "", "%.2f" % hidden["information_criterion_delta"] if hidden else "",
          str(hidden["significant"]).lower() if hidden else "", top["mechanism"], "%.4f" % top["heldout_gain"],
          "%.1f" % d["wall_time_s"], d.get("footprint") or "",
          str(d["baseline"]["adequacy"]["adequate"]).lower(), "%.3g" % d["baseline"]["adequacy"]["goodness_of_fit"]["p_value"]]
print(",".join(fields))
PY
  if [ -n "${KEEP:-}" ]; then
    mkdir -p "$KEEP"
    cp "$dir/diagnosis/diagnosis.json" "$KEEP/$effect-$seed-diagnosis.json"
    [ ! -f "$dir/truth.json" ] || cp "$dir/truth.json" "$KEEP/$effect-$seed-truth.json"
  fi
  /usr/bin/python3 "$(dirname "$0")/parameter_rows.py" "$dir/diagnosis/diagnosis.json" "$dir/truth.json" "$effect" "$seed" >>"$parameters_out"
  tail -n 1 "$out"
}

for_each_new_set "$out" "$seeds" "$first" "$effects" diagnose_set

/usr/bin/python3 - "$out" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("%-34s %6s %8s %12s" % ("hidden", "sets", "correct", "rate"))
for effect in dict.fromkeys(r["hidden"] for r in rows):
    mine = [r for r in rows if r["hidden"] == effect]
    right = sum(r["cause"] == effect for r in mine)
    label = "none (false alarms: %d)" % (len(mine) - right) if effect == "none" else effect
    print("%-34s %6d %8d %11.0f%%" % (label, len(mine), right, 100.0 * right / len(mine)))
PY
