#!/usr/bin/env bash
# The brush's cost in the window (skylit view under xvfb-run, --camera-log's shading_ms):
# the sample glider followed at 1280×720, one raise click at the window's centre, with the
# incremental refresh (--refresh-frames 32) and with the whole recompute (0). Prints the
# median shading of the frames before the click, the click's frame, and the median of
# the refresh frames after it. Usage: scripts/bench_brush.sh [build dir] [scene sides...]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_common.sh
bin=${1:-build}/bin/skylit
shift || true
[[ $# -gt 0 ]] && sides=("$@") || sides=(512 1024)
print_machine
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
click=6 last=44
printf '0 press b\n%s click 640 360\n%s quit\n' "$click" "$last" > "$out/s.txt"
median() { sort -n | awk '{a[NR]=$1} END {print (NR ? a[int((NR+1)/2)] : "n/a")}'; }
runs=${runs:-3}
for side in "${sides[@]}"; do
  for n in 32 0; do
    rows=()
    for ((r = 0; r < runs; ++r)); do
      xvfb-run -a -s "-screen 0 1280x720x24" "$bin" view --synthetic --scene-size "$side" \
        --track data/tracks/sample_glider.igc --width 1280 --height 720 --script "$out/s.txt" \
        --refresh-frames "$n" --camera-log "$out/c.csv" > "$out/log.txt" 2>&1 ||
        { echo "${side}² --refresh-frames $n: FAILED"; cat "$out/log.txt"; continue 2; }
      # Columns: frame, ..., shading_ms (8), horizons_computed (9), stale_texels (10).
      rows+=("$(awk -F, -v c="$click" '
        NR == 1 {next}
        $1 >= 2 && $1 < c {before[++nb] = $8}
        $1 == c {edit = $8}
        $1 > c && $10 > 0 {refresh[++nr] = $8}
        $1 > c + 1 && $10 == 0 && $9 == 0 {after[++na] = $8}
        function med(a, n,   i, j, t) {  # insertion sort (mawk has no asort)
          for (i = 2; i <= n; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
          return n ? a[int((n + 1) / 2)] : -1 }
        END {printf "%.0f %.0f %.0f %d %.0f\n", med(before, nb), edit, med(refresh, nr), nr, med(after, na)}' "$out/c.csv")")
    done
    # The median run by its edit frame.
    printf '%s\n' "${rows[@]}" | sort -n -k2 | awk -v s="$side" -v n="$n" -v runs="$runs" '{a[NR] = $0}
      END {split(a[int((NR + 1) / 2)], f, " ");
        printf "%5s² --refresh-frames %-2s  before %5d ms  edit frame %5d ms  refresh %5s ms (%d frames)  after %5d ms  (median of %d runs)\n",
          s, n, f[1], f[2], f[3] < 0 ? "-" : f[3], f[4], f[5], runs}'
  done
done
