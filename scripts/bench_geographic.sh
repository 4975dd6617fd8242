#!/usr/bin/env bash
# Issue 17's geographic target: the franconia 1201² SRTM tile in EPSG:4326 against its
# reprojection to UTM 32N at the same size (gdalwarp -r cubic), `shade -p shaded` at
# default quality, wall time including I/O; also the march the geographic tile ran
# before the rhumb-line sweep. Usage: scripts/bench_geographic.sh [RUNS] [BACKEND]
# after a release build; needs ../shared/dem. Prints best and median per command and
# the ratios of the best times.
set -euo pipefail
runs=${1:-3}
backend=${2:-auto}
here=$(cd "$(dirname "$0")/.." && pwd)
skylit="$here/build/bin/skylit"
dem="$here/../shared/dem/franconia_hills_srtm3_4326.tif"
[ -f "$dem" ] || { echo "bench_geographic: $dem not found" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
gdalwarp -q -t_srs EPSG:32632 -r cubic -ts 1201 1201 "$dem" "$tmp/utm.tif"

. "$here/scripts/bench_common.sh"

print_machine
echo "backend: $backend"
out=$(mktemp)
time_runs "geographic 1201² (EPSG:4326) -p shaded, sweep" \
  "$skylit" shade "$dem" -o "$tmp/geo.png" -p shaded -q --overwrite --backend "$backend" | tee -a "$out"
time_runs "UTM 32N twin 1201² -p shaded, sweep" \
  "$skylit" shade "$tmp/utm.tif" -o "$tmp/utm.png" -p shaded -q --overwrite --backend "$backend" | tee -a "$out"
time_runs "geographic 1201² -p shaded --horizons march" \
  "$skylit" shade "$dem" -o "$tmp/march.png" -p shaded -q --overwrite --backend "$backend" --horizons march |
  tee -a "$out"
awk '{for (i = 1; i <= NF; ++i) if ($i == "best") b[NR] = $(i + 1)}
     END {printf "geographic / UTM: %.2f×   march / geographic sweep: %.2f×\n", b[1] / b[2], b[3] / b[1]}' "$out"
rm -f "$out"
