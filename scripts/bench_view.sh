#!/usr/bin/env bash
# The viewer's frame time per pass (skylit render --timings: each pass finished before
# the next), on the synthetic scene with the sample glider: 1024² at 1280×720 (the
# llvmpipe target) and, with a GPU, 4096² at 1920×1080. The first frame's shading is the
# horizons' recompute of the whole field. Usage: scripts/bench_view.sh [build dir]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_common.sh
bin=${1:-build}/bin/skylit
print_machine
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run() {  # scene side, WxH
  echo "== ${1}² at $2"
  "$bin" render --synthetic --scene-size "$1" --track data/tracks/sample_glider.igc --size "$2" --fps 1 \
    --duration 5 -o "$out/f_$1_%d.png" --timings -q
}
run 1024 1280x720
probe=$("$bin" render --synthetic --scene-size 16 --time 2026-06-21T10:00Z --size 16x16 --duration 0 \
  -o "$out/probe_%d.png" 2>&1)
if [[ $probe != *llvmpipe* ]]; then
  run 4096 1920x1080
else
  echo "(4096² at 1920x1080: skipped on a software rasterizer)"
fi
