#!/usr/bin/env bash
# The guards a trusted project runs on itself, in a build of their own (build-sanitized/,
# clang): the solver's, the scene loader's and capture's tests under AddressSanitizer and UBSan,
# then the fuzzers of the scene loader and of --set for a bounded time each, seeded
# with the shipped presets. Fails on any test failure, sanitizer report, crash,
# uncaught exception or timeout. Needs clang (third_party/install_deps.sh --fuzz).
#   usage: src/tests/run_sanitized.sh [SECONDS per fuzzer, default 30]
# Run the fuzzers longer by giving more seconds; what they find stays in
# build-sanitized/corpus_* and, for a crash, build-sanitized/crash-*.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-30}"
out=build-sanitized
cmake -S . -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPHERES_SANITIZED=ON \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$out"
ctest --test-dir "$out" --output-on-failure -j2

mkdir -p "$out/corpus_scene_file" "$out/corpus_set"
cp assets/scenes/*.json "$out/corpus_scene_file/"
# --set seeds: a byte that picks the preset, then "name=value"; one per parameter.
i=0
for setting in alpha=0.5 beta=1 epsilon=0 mu=1 h=0.001 substeps=8 passes=10 gravity=50 method=velocity \
               response=momentum split=mass order=shuffled threads=2 broadphase=allpairs count=5000 \
               radius=0.02 seed=7 emit_period=0.5; do
  printf "\\x$(printf %02x $((i % 13)))%s" "$setting" > "$out/corpus_set/seed_$i"
  i=$((i + 1))
done
# Both fuzzers at once, one a core (each is single-threaded): the same seconds each, half the wait.
declare -A pid
for fuzzer in scene_file set; do
  "$out/spheres_fuzz_$fuzzer" "$out/corpus_$fuzzer" -max_total_time="$seconds" -artifact_prefix="$out/" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 >"$out/fuzz_$fuzzer.log" 2>&1 &
  pid[$fuzzer]=$!
done
trap 'kill "${pid[@]}" 2>/dev/null || true' EXIT  # a failure of one does not leave the other running
for fuzzer in scene_file set; do
  log="$out/fuzz_$fuzzer.log"
  status=0
  wait "${pid[$fuzzer]}" || status=$?
  unset "pid[$fuzzer]"  # reaped: the trap must not signal a number the system may give another
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  echo "spheres_fuzz_$fuzzer: $runs inputs in $seconds s, exit $status"
  if [ "$status" -ne 0 ]; then
    grep -E "ERROR|runtime error|SUMMARY|uncaught|deadly" "$log" | head -20
    echo "spheres_fuzz_$fuzzer found a problem: see $log and the input $out/crash-* (or timeout-*)"
    exit 1
  fi
done
