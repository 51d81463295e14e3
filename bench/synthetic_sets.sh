# Sourced by the scripts that run over synthetic measured-data sets (diagnosis_success.sh,
# truth_detectability.sh); they set $caskdem first.
#
#   for_each_new_set OUT_CSV SEEDS FIRST_SEED "EFFECTS" FUNCTION
#
# For each seed (FIRST_SEED on, SEEDS of them) and each effect ("none": the baseline alone)
# that OUT_CSV has no row for yet (rows start "effect,seed,"), writes the data set of
# `caskdem synthesize-measured` (or, with GENERATOR set to the path of the independent
# generator, build/tests/independent/caskdem_independent_data, its data) into a fresh directory, calls FUNCTION DIRECTORY EFFECT SEED
# (which appends the rows) and removes the directory: a stopped run resumes where it stopped.
for_each_new_set() {
  set_rows=$1 set_seeds=$2 set_first=$3 set_effects=$4 set_function=$5
  set_work=$(mktemp -d)
  trap 'rm -rf "$set_work"' EXIT
  set_index=0
  while [ "$set_index" -lt "$set_seeds" ]; do
    set_seed=$((set_first + set_index))
    for set_effect in $set_effects; do
      if grep -q "^$set_effect,$set_seed," "$set_rows"; then continue; fi
      set_dir="$set_work/$set_effect-$set_seed"
      if [ -n "${GENERATOR:-}" ]; then  # the independent generator (tests/independent)
        "$GENERATOR" --out "$set_dir" --seed "$set_seed" --effect "$set_effect" >/dev/null
      elif [ "$set_effect" = none ]; then
        "$caskdem" synthesize-measured --out "$set_dir" --seed "$set_seed" >/dev/null
      else
        "$caskdem" synthesize-measured --out "$set_dir" --seed "$set_seed" --effect "$set_effect" >/dev/null
      fi
      "$set_function" "$set_dir" "$set_effect" "$set_seed"
      rm -rf "$set_dir"
    done
    set_index=$((set_index + 1))
  done
}
