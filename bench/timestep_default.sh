#!/usr/bin/env bash
# The ensembles' default step verified on the fragility (docs/time-step.md, "The default step,
# measured on every shipped ensemble"): every shipped ensemble at four times its realisations per
# stripe, the whole-step slider at f_s 0.01 to 0.07 and the source paper's scheme (half-step
# slider, 0.01), each against the whole-step slider at 0.005 on the same realisations. Rows are
# appended to ROWS.csv; bench/timestep_table.py ROWS.csv makes the table (single-motion runs
# judged against their shipped band, several motions against their own).
#
#   bench/timestep_default.sh [BUILD] [ROWS.csv] [VARIANTS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
rows=${2:-bench/results/timestep-default.csv}
variants=${3:-0.005:1:whole-step,0.01:1:whole-step,0.02:1:whole-step,0.03:1:whole-step,0.05:1:whole-step,0.06:1:whole-step,0.07:1:whole-step,0.01:1:half-step}
for file in ensembles/*.toml; do
  per_stripe=$(awk '/^\[intensity\]/ {i = 1} i && /^realisations *=/ {print $3; exit}' "$file")
  measure=$(awk '/^\[intensity\]/ {i = 1} i && /^measure *=/ {gsub(/"/, "", $3); print $3; exit}' "$file")
  # A 1/3 model's PGV is the prototype's over sqrt 3 (caskdem risk --similarity); PGA is the same.
  case "$(basename "$file")" in
    full-scale-*) similarity=1 ;;
    *) similarity=3 ;;
  esac
  "$build/bench/timestep_convergence" "$file" --variants "$variants" --per-stripe $((4 * per_stripe)) \
    --hazard "hazard/example-site-$measure.csv" --similarity "$similarity" --csv "$rows"
done
