#!/usr/bin/env bash
# The GPU engine's check, for a session lent a machine with one GPU (the device tool: one short
# call, 15 minutes of device time a session). Two halves:
#
#   bench/device-check.sh prepare   on this machine (no GPU): builds build-device/ (Release, the
#                                   CUDA engine for sm_90 with the CUDA runtime linked statically,
#                                   no MPI), gathers into .device/ the three programs, the shared
#                                   libraries they take from Debian (the GPU machine's image has
#                                   none of Debian's -dev packages) and the recorded motions the
#                                   shipped ensembles read, checks that it is under 56 MiB, and
#                                   prints the device call.
#   bench/device-check.sh run       on the GPU machine, from the repository root, with .device/
#                                   carried: the bit-for-bit tests (test_gpu: the lane arithmetic,
#                                   every realisation of every shipped ensemble planar and 3D, and
#                                   `caskdem ensemble --device auto` against `--device cpu`), then
#                                   the benchmarks (bench_device: the kernel, 10^4, 10^5 and 10^6
#                                   realisations x 20 s of El Centro, the 3D benchmark, each beside
#                                   the same machine's CPU cores where the issue asks for the ratio),
#                                   and one summary table. Everything goes to $OUT (the device
#                                   tool brings it back): device-check.log, test_gpu.xml,
#                                   bench_device.json, summary.txt.
#
# DEVICE_CHECK_BENCHMARKS, a regular expression, runs some of the benchmarks only (a rerun).
#
# The device call, once `prepare` has run:
#   run(command="bench/device-check.sh run", carry=[".device"], timeout_s=540)
set -euo pipefail
cd "$(dirname "$0")/.."
stage=.device

prepare() {
  cmake -S . -B build-device -DCMAKE_BUILD_TYPE=Release -DCASKDEM_WITH_CUDA=ON -DCASKDEM_WITH_MPI=OFF \
    -DCASKDEM_BUILD_TESTS=ON -DCASKDEM_BUILD_BENCHMARKS=ON >/dev/null
  cmake --build build-device -j"$(nproc)" --target caskdem test_gpu bench_device
  rm -rf "$stage"
  mkdir -p "$stage/bin" "$stage/lib" "$stage/shared"
  cp build-device/src/caskdem build-device/tests/gpu/test_gpu build-device/bench/bench_device "$stage/bin/"
  strip "$stage"/bin/*
  # Every shared library the programs load, but the C and C++ runtimes (the GPU machine's are
  # newer, and take programs built against older ones).
  for program in "$stage"/bin/*; do
    ldd "$program" | awk '/=> \// {print $3}'
  done | sort -u | grep -Ev '/(libc|libm|libdl|librt|libpthread|libresolv|libutil|libstdc\+\+|libgcc_s|ld-linux-x86-64)\.so' |
    while read -r library; do cp -L "$library" "$stage/lib/"; done
  cp -r ../shared/motions "$stage/shared/"
  # The paths the programs were built with: the repository (ensembles/, the caskdem binary) and
  # the shared folder beside it, which `run` recreates as links on the GPU machine.
  pwd -P >"$stage/source_dir"
  local size
  size=$(du -sm "$stage" | cut -f1)
  echo "device-check: $stage holds $size MiB (programs, $(ls "$stage/lib" | wc -l) libraries, motions)"
  [ "$size" -le 56 ] || { echo "device-check: $stage is over 56 MiB; the device tool carries 64 MiB with the tree" >&2; exit 1; }
  grep -qx '/.device/' .gitignore || { echo "device-check: .gitignore must ignore /.device/" >&2; exit 1; }
  echo 'device-check: now call the device tool: run(command="bench/device-check.sh run", carry=[".device"], timeout_s=540)'
}

run() {
  [ -d "$stage/bin" ] || { echo "device-check: no $stage/bin: run 'bench/device-check.sh prepare' here first" >&2; exit 2; }
  out=${OUT:-$PWD/device-check-out}
  mkdir -p "$out"
  exec > >(tee "$out/device-check.log") 2>&1
  export LD_LIBRARY_PATH="$PWD/$stage/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  # The programs read the repository where it was built and ../shared beside it: make both paths
  # lead here.
  built=$(cat "$stage/source_dir")
  if [ "$(pwd -P)" != "$built" ]; then
    mkdir -p "$(dirname "$built")"
    [ -e "$built" ] || ln -s "$PWD" "$built"
  fi
  [ -e "$(dirname "$built")/shared" ] || ln -s "$PWD/$stage/shared" "$(dirname "$built")/shared"
  # test_gpu runs the caskdem binary where it was built.
  mkdir -p "$built/build-device/src"
  [ -e "$built/build-device/src/caskdem" ] || ln -s "$PWD/$stage/bin/caskdem" "$built/build-device/src/caskdem"
  echo "== machine"
  nvidia-smi --query-gpu=name,memory.total,clocks.max.sm,driver_version --format=csv || true
  echo "cpu: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
  echo "== bit for bit: the GPU against the CPU (test_gpu)"
  local tests=0
  "$stage/bin/test_gpu" --gtest_output="xml:$out/test_gpu.xml" || tests=$?
  echo "== memory check: a small ensemble on the GPU under compute-sanitizer (memcheck)"
  local memcheck=0
  if command -v compute-sanitizer >/dev/null; then
    timeout 90 compute-sanitizer --tool memcheck --error-exitcode 3 "$stage/bin/caskdem" ensemble \
      tests/ensemble/data/mixed-outcomes.toml --device cuda --no-plot --quiet --out "$out/memcheck.h5" || memcheck=$?
  else
    echo "no compute-sanitizer on this machine"
  fi
  echo "== benchmarks (bench_device)"
  local benches=0
  timeout 420 "$stage/bin/bench_device" --benchmark_out="$out/bench_device.json" --benchmark_out_format=json \
    --benchmark_counters_tabular=true --benchmark_filter="${DEVICE_CHECK_BENCHMARKS:-.}" || benches=$?
  echo "== summary"
  summary "$out" | tee "$out/summary.txt" || true
  echo "test_gpu exit $tests, compute-sanitizer exit $memcheck, bench_device exit $benches"
  [ "$tests" -eq 0 ] && [ "$benches" -eq 0 ] && [ "$memcheck" -eq 0 ]
}

# One table from the benchmark file: each case's wall time and the ratios the issue asks for.
summary() {
  python3 - "$1/bench_device.json" <<'PYTHON'
import json, sys
try:
    data = json.load(open(sys.argv[1]))
except (OSError, ValueError) as error:
    sys.exit(f"no benchmark results: {error}")
context = data["context"]
print(f"GPU {context.get('gpu')}, FP64 peak {context.get('gpu_fp64_peak_tflops')} TFLOP/s; "
      f"CPU {context.get('cpu_threads')} threads, {context.get('best_instruction_set')}")
runs = {b["name"].split("/")[0] + "/" + b["name"].split("/")[1]: b for b in data["benchmarks"]}
print(f"{'case':32} {'wall s':>9} {'realisations':>13} {'real-s/s':>12}  note")
for name, b in runs.items():
    if b.get("error_occurred"):
        print(f"{name:32} {'-':>9} {'-':>13} {'-':>12}  {b.get('error_message')}")
        continue
    seconds = b["real_time"] if b.get("time_unit") == "s" else b["real_time"] / 1e9
    note = ""
    if "fp64_fraction" in b:
        note = f"{b['realisation_steps_per_s']:.3g} realisation-steps/s, {100 * b['fp64_fraction']:.1f} % of FP64 peak"
    elif "realisation_steps_per_s" in b:
        note = f"{b['realisation_steps_per_s']:.3g} realisation-steps/s"
    print(f"{name:32} {seconds:9.2f} {b.get('realisations', 0):13.0f} {b.get('realisation_seconds_per_s', 0):12.4g}  {note}")
def wall(name):
    b = runs.get(name)
    return None if not b or b.get("error_occurred") else b["real_time"]
for gpu, cpu, label in [("ensemble/device_10k", "ensemble/cpu_10k", "10^4 x 20 s"),
                        ("ensemble/device_100k", "ensemble/cpu_100k", "10^5 x 20 s"),
                        ("ensemble/device_3d_1k", "ensemble/cpu_3d_1k", "3D 10^3 x 20 s")]:
    g, c = wall(gpu), wall(cpu)
    if g and c:
        print(f"{label}: GPU {g:.2f} s, CPU {c:.2f} s: {c / g:.1f} times faster")
million = wall("ensemble/device_1m")
if million:
    print(f"10^6 x 20 s on the GPU: {million:.1f} s (fragility written: {runs['ensemble/device_1m'].get('fragility_written')})")
PYTHON
}

case "${1:-}" in
  prepare) prepare ;;
  run) run ;;
  *) echo "usage: bench/device-check.sh prepare|run" >&2; exit 2 ;;
esac
