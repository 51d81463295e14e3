#!/usr/bin/env bash
# The test suite under sanitizers (docs/fuzzing.md, "Sanitizer builds"); scripts/test.sh runs both.
#
#   scripts/sanitize.sh address [CTEST_ARGS...]   AddressSanitizer + UndefinedBehaviorSanitizer,
#                                                 the whole suite but the full diagnoses, into
#                                                 build-asan/
#   scripts/sanitize.sh thread  [CTEST_ARGS...]   ThreadSanitizer, the ensemble tests, into
#                                                 build-tsan/
#
# The address build uses the default compiler (g++) with its libgomp. The thread build uses
# clang with LLVM's libomp and its Archer tool (OMP_TOOL_LIBRARIES), which tells TSan about
# OpenMP's barriers and tasks; libgomp is not instrumented and would report races that are
# not there. Every finding aborts the test that made it, so ctest fails.
set -euo pipefail
cd "$(dirname "$0")/.."
kind=${1:?"usage: scripts/sanitize.sh address|thread [CTEST_ARGS...]"}
shift
jobs=$(nproc)
targets=()
# Tests that repeat, three to ten times slower instrumented, work that the others run once:
# one cask run many times to compare its bits across instruction sets, thread counts, block sizes
# and engines, where a planar twin or a single run of the same code stays in, and a fit scanned
# point by point.
repeats=$(
  IFS='|'
  list=(
    'Cask3D\.AnEccentricCentreOfMassRocksFirstTowardsItsSide'
    'Cask3DLanes\.BlocksGiveTheDeterministicRunsBitsOnEveryInstructionSet'
    'Ensemble3D\.EveryLaneEqualsTheDeterministicRun'
    'Ensemble3D\.PaperSchemeSameBitsOnEveryInstructionSetThreadCountBlockSizeAndSchedule'
    'Reproducibility\.RefilledLanesGiveTheLockstepBits'
    'ReproducibilityDistributed\.SameBitsOnEveryInstructionSet'
    'Resume\.Killed3DRunResumesToTheUninterruptedResult'
    'Adequacy\.TheBaselineOnItsOwnRuleFitsAndOnTheWrongRuleDoesNot'
    'PlanTest\.CandidatesThatPredictAlikeAreNotSeparated'
    'TableInputs/AtAFitsOwnPoint\.'
    'PlanarAnd3D/(DeviceLanes|Rollout)Test\..*/spatial'
  )
  echo "${list[*]}"
)
# Under AddressSanitizer, also the studies that run one code many times over to measure a
# number (a convergence order, a threshold found by bisection, an interval's coverage, the same
# ensemble's bits on every block size, thread count or instruction set once more), and the docs'
# Python recipe, whose instrumented part is an ensemble run other tests make: each took 30 s to
# 2 min instrumented on a two-core AMD EPYC, where the suite's shorter tests run the same code
# once. The ensemble on every instruction set stays in (Reproducibility.SameBitsOnEvery-
# InstructionSet): it is what runs each instruction set's kernel under the sanitizers.
studies=$(
  IFS='|'
  list=(
    'Sliding\.WholeStepSliderIsSecondOrder'
    'Pulses\.HalfSineOverturningThresholdFollowsTheClosedForm'
    'Convergence\.TheCaskIn3DUnderAStationsThreeComponents'
    'NestedFragility\.RecoversTheTwoLevelModelAndItsIntervalsCoverTheTruth'
    'Agreement\.EveryLaneEqualsTheDeterministicRun'
    'Reproducibility\.(PaperSchemeSameBitsOnEveryInstructionSetAndThreadCount|SameBitsWhateverTheBlockSize)'
    'Reproducibility\.SameBitsOnOneTwoAndThreeThreads'
    'CommandLine\.AnInstructionSetTheMachineLacksIsRefusedFirst'
    'OutputFormats\.TheDocsPythonRecipeRuns'
  )
  echo "${list[*]}"
)

case "$kind" in
  address)
    build=build-asan
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCASKDEM_SANITIZE=address,undefined \
      -DCASKDEM_BUILD_TESTS=ON -DCASKDEM_BUILD_BENCHMARKS=OFF >/dev/null
    export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:check_initialization_order=1:strict_string_checks=1"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    ;;
  thread)
    build=build-tsan
    compiler=$(command -v clang++-15 || command -v clang++ || true)
    [ -n "$compiler" ] || { echo "sanitize.sh: no clang++; scripts/install-deps.sh installs it" >&2; exit 2; }
    archer=$(realpath -m "$("$compiler" -print-resource-dir)/../../libarcher.so")  # LLVM's lib/
    [ -f "$archer" ] || { echo "sanitize.sh: no libarcher.so beside $compiler (libomp-dev)" >&2; exit 2; }
    CC=${compiler/clang++/clang} CXX=$compiler cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCASKDEM_SANITIZE=thread -DCASKDEM_BUILD_TESTS=ON -DCASKDEM_BUILD_BENCHMARKS=OFF -DCASKDEM_WITH_MPI=OFF \
      >/dev/null
    export OMP_TOOL_LIBRARIES="$archer"
    # libomp itself is not instrumented; Archer asks TSan to ignore what it does alone.
    export TSAN_OPTIONS="ignore_noninstrumented_modules=1:halt_on_error=1:second_deadlock_stack=1"
    [ $# -gt 0 ] || set -- -L ensemble -E "^($repeats)"
    targets=(--target caskdem test_ensemble test_ensemble_engine)
    ;;
  *)
    echo "sanitize.sh: '$kind': expected address or thread" >&2
    exit 2
    ;;
esac

cmake --build "$build" -j"$jobs" "${targets[@]}"
if [ "$kind" = address ] && [ $# -eq 0 ]; then
  # Everything but the repeats, the full diagnoses at shipped settings (label diagnosis-full;
  # test_decision_invariants.cpp runs the whole diagnosis on a small search) and the README's
  # tour (label tour; each of its commands has its own test); the 3D ensemble's run on every
  # thread count stays in under ThreadSanitizer alone, where it is the 3D engine's thread test.
  ctest --test-dir "$build" --output-on-failure --no-tests=error -j"$jobs" -LE 'diagnosis-full|diagnosis-more|tour' \
    -E "^(Mpi\.|Ensemble3D\.SameBitsOnEveryInstructionSetThreadCountBlockSizeAndSchedule|$repeats|$studies)"
  # OpenMPI unloads its plugins before the leak check, so what they keep shows with no module
  # name and no suppression can match it: the MPI tests run with every check but that one.
  ASAN_OPTIONS=${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0} \
    ctest --test-dir "$build" --output-on-failure --no-tests=ignore -j"$jobs" -R '^Mpi\.'
else
  ctest --test-dir "$build" --output-on-failure --no-tests=error -j"$jobs" "$@"
fi
