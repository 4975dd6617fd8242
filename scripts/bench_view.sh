#!/usr/bin/env bash
# The viewer's frame time per pass (skylit render --timings: each pass finished before
# the next), on the synthetic scene with the sample glider: 1024² at 1280×720 (the
# llvmpipe target) with one and five aircraft and, with a GPU, 4096² at 1920×1080 with
# five (the sample glider and four copies flown 0.6 and 1.2 km north and south of it).
# The first frame's shading is the horizons' recompute of the whole field.
# Usage: scripts/bench_view.sh [build dir]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_common.sh
bin=${1:-build}/bin/skylit
print_machine
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# The sample glider's B records moved north by $1 km (1' of latitude = 1.852 km).
shifted_track() {
  python3 - "$1" data/tracks/sample_glider.igc <<'PY'
import sys
km, path = float(sys.argv[1]), sys.argv[2]
for line in open(path):
    if line.startswith("B") and len(line) > 14:
        milli = int(line[7:9]) * 60000 + int(line[9:14]) + round(km / 1.852 * 1000)
        line = line[:7] + "%02d%05d" % divmod(milli, 60000) + line[14:]
    sys.stdout.write(line)
PY
}
tracks=(--track data/tracks/sample_glider.igc)
five=("${tracks[@]}")
for km in -1.2 -0.6 0.6 1.2; do
  shifted_track "$km" > "$out/glider_$km.igc"
  five+=(--track "$out/glider_$km.igc")
done
run() {  # scene side, WxH, label, track options...
  local side=$1 size=$2 label=$3
  shift 3
  echo "== ${side}² at $size, $label"
  "$bin" render --synthetic --scene-size "$side" "$@" --size "$size" --fps 1 \
    --duration 5 -o "$out/f_${side}_%d.png" --overwrite --timings -q
}
run 1024 1280x720 "one aircraft" "${tracks[@]}"
run 1024 1280x720 "five aircraft" "${five[@]}"
probe=$("$bin" render --synthetic --scene-size 16 --time 2026-06-21T10:00Z --size 16x16 --duration 0 \
  -o "$out/probe_%d.png" 2>&1)
if [[ $probe != *llvmpipe* ]]; then
  run 4096 1920x1080 "five aircraft" "${five[@]}"
else
  echo "(4096² at 1920x1080: skipped on a software rasterizer)"
fi
