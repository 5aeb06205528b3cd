#!/usr/bin/env bash
# Builds the fuzzers with clang (build-fuzz/, beside build/) and runs each for a bounded
# time, seeded with the shipped presets; fails on any crash, sanitizer report, uncaught
# exception or timeout. Usage: src/tests/fuzz/run_fuzzers.sh [SECONDS per fuzzer, default 30]
# (run it longer by giving more seconds: new inputs stay in build-fuzz/corpus_*).
set -euo pipefail
cd "$(dirname "$0")/../../.."
seconds="${1:-30}"
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPHERES_FUZZ=ON \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz
mkdir -p build-fuzz/corpus_scene_file build-fuzz/corpus_set
cp assets/scenes/*.json build-fuzz/corpus_scene_file/
# --set seeds: a preset byte, then "name=value"; one per parameter of the table.
i=0
for setting in alpha=0.5 beta=1 epsilon=0 mu=1 h=0.001 substeps=8 passes=10 gravity=50 method=velocity \
               response=momentum split=mass order=shuffled threads=2 broadphase=allpairs count=5000 \
               radius=0.02 seed=7 emit_period=0.5; do
  printf "\\x$(printf %02x $((i % 13)))%s" "$setting" > "build-fuzz/corpus_set/seed_$i"
  i=$((i + 1))
done
for fuzzer in scene_file set; do
  log="build-fuzz/fuzz_$fuzzer.log"
  status=0
  build-fuzz/spheres_fuzz_$fuzzer build-fuzz/corpus_$fuzzer \
    -max_total_time="$seconds" -artifact_prefix=build-fuzz/ -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 >"$log" 2>&1 || status=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  echo "spheres_fuzz_$fuzzer: $runs inputs in $seconds s, exit $status"
  if [ "$status" -ne 0 ]; then
    grep -E "ERROR|runtime error|SUMMARY|uncaught|deadly" "$log" | head -20
    echo "spheres_fuzz_$fuzzer found a problem: $log, the input in build-fuzz/ (crash-*, timeout-*)"
    exit 1
  fi
done
