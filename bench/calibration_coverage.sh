#!/bin/sh
# Do the standard errors of `caskdem calibrate-measured` cover the true values? For SEEDS
# synthetic data sets of the baseline model plus sensor noise (`caskdem synthesize-measured`),
# the baseline is calibrated with each way of making standard errors (--uncertainty curvature
# and jackknife), and every parameter's true value (the generator's truth.json, which the fit
# never sees), fitted value and standard error is one CSV row, for
# bench/parameter_coverage.py.
#
#   bench/calibration_coverage.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED]
#
# About 10 s (curvature) and 60 s (jackknife) per data set on 2 cores. Appends to OUT_CSV, so a
# stopped run resumes.
set -eu
build=${1:?usage: calibration_coverage.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED]}
out=${2:?usage: calibration_coverage.sh BUILD_DIR OUT_CSV [SEEDS] [FIRST_SEED]}
seeds=${3:-12}
first=${4:-1001}
caskdem="$build/src/caskdem"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -s "$out" ] || echo "hidden,seed,model,parameter,truth,fitted,standard_error,at_search_bound,training_objective,training_residuals,method" >"$out"

i=0
while [ "$i" -lt "$seeds" ]; do
  seed=$((first + i))
  dir="$work/none-$seed"
  for method in curvature jackknife; do
    if grep -q "^none,$seed,.*,$method\$" "$out"; then continue; fi
    [ -d "$dir" ] || "$caskdem" synthesize-measured --out "$dir" --seed "$seed" >/dev/null
    "$caskdem" calibrate-measured "$dir" --quiet --uncertainty "$method" --out "$dir/$method" >/dev/null
    /usr/bin/python3 "$(dirname "$0")/parameter_rows.py" "$dir/$method/calibration.json" "$dir/truth.json" none "$seed" "$method" >>"$out"
  done
  rm -rf "$dir"
  i=$((i + 1))
done
/usr/bin/python3 "$(dirname "$0")/parameter_coverage.py" "$out"
