#!/usr/bin/env bash
# Fuzzes each track reader with libFuzzer for SECONDS (default 120) and folds the inputs
# that found new coverage into fuzz/corpus/<reader>/, minimised (-set_cover_merge=1: a greedy minimum set with the same coverage), so the
# corpus stays small (coverage edges, not hit counts: -use_counters=0). SECONDS 0 only
# minimises. Crashes are left as crash-* files in build-fuzz/ and fail the run.
# Needs clang-16 (apt: clang-16 libclang-rt-16-dev).
# Usage: scripts/fuzz.sh [SECONDS] [READER...]   (readers: igc gpx kml csv)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-120}
shift || true
readers=("$@")
[ ${#readers[@]} -gt 0 ] || readers=(igc gpx kml csv)

cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-16 -DCMAKE_CXX_COMPILER=clang++-16 \
  -DSKYLIT_BUILD_FUZZERS=ON -DSKYLIT_BUILD_TESTS=OFF -DSKYLIT_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz --target "${readers[@]/#/fuzz_}"

for r in "${readers[@]}"; do
  corpus="fuzz/corpus/$r"
  work=$(mktemp -d)
  if [ "$seconds" -gt 0 ]; then
    echo "fuzz: $r for ${seconds}s"
    (cd build-fuzz && ./bin/fuzz_"$r" -max_total_time="$seconds" -max_len=8192 -timeout=10 \
        -print_final_stats=1 "$work" "../$corpus")
  fi
  minimised=$(mktemp -d)
  build-fuzz/bin/fuzz_"$r" -set_cover_merge=1 -use_counters=0 "$minimised" "$corpus" "$work" >/dev/null 2>&1
  rm -rf "$work"
  # Keep the hand-written seeds (readable names); replace the found inputs (named by
  # their SHA-1) by the minimised set, less what duplicates a seed.
  find "$corpus" -type f -regextype posix-extended -regex '.*/[0-9a-f]{40}' -delete
  for seed in "$corpus"/*; do rm -f "$minimised/$(sha1sum "$seed" | cut -d' ' -f1)"; done
  cp "$minimised"/* "$corpus"/ 2>/dev/null || true
  rm -rf "$minimised"
  echo "fuzz: $r corpus now $(find "$corpus" -type f | wc -l) files"
done
