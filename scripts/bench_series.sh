#!/usr/bin/env bash
# Time series and the renderer, end to end, in one sitting (issue 13's measurements):
# a single `shade -p shaded` against the previous binary ($OLD, built from an earlier
# commit in a worktree) and gdaldem; 24-frame `shadow` and `shaded` series against one
# frame; a day's insolation against GRASS r.sun (mode 2) and SAGA's Potential Incoming
# Solar Radiation on the same DEM when they are installed (apt-get install grass-core
# saga). Their clear-sky models and defaults are their own: the daily means printed
# beside the times say whether the runs are comparable. Usage: OLD=/path/to/old/skylit scripts/bench_series.sh [SIZE] [RUNS] after a
# release build. Prints one line per command: best and median wall time over RUNS.
set -euo pipefail
size=${1:-1024}
runs=${2:-3}
ext_runs=${EXT_RUNS:-1}  # r.sun and SAGA take minutes at 1024²
here=$(cd "$(dirname "$0")/.." && pwd)
skylit="$here/build/bin/skylit"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$skylit" scene -o "$tmp/dem.tif" --size "$size" -q
day=2026-06-21
series="${day}T04:00Z/${day}T15:30Z/PT30M"  # 24 frames (the scene at 7.9° E: 04:32–16:02 local mean time)

. "$here/scripts/bench_common.sh"

print_machine
"$skylit" shade "$tmp/dem.tif" -o "$tmp/probe.tif" -p svf --azimuths 1 2>&1 | tr '\r' '\n' | grep 'computed on' || true
time_runs "gdaldem hillshade -multidirectional ${size}² (PNG)" \
  gdaldem hillshade -multidirectional -q -of PNG "$tmp/dem.tif" "$tmp/gd.png"
if [ -n "${OLD:-}" ]; then
  time_runs "previous binary: shade ${size}² -p shaded" "$OLD" shade "$tmp/dem.tif" -o "$tmp/old.png" -p shaded -q --overwrite
fi
time_runs "shade ${size}² -p shaded (one frame)" "$skylit" shade "$tmp/dem.tif" -o "$tmp/one.png" -p shaded -q --overwrite
time_runs "shade ${size}² -p shaded --time (one frame at $day 10:00Z)" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/one_t.png" -p shaded --time "${day}T10:00Z" -q --overwrite
time_runs "shade ${size}² -p shaded, 24-frame series" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/f_%02d.png" -p shaded --time "$series" -q --overwrite
time_runs "shade ${size}² -p shadow (one frame at $day 10:00Z)" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/s1.tif" -p shadow --time "${day}T10:00Z" -q --overwrite
time_runs "shade ${size}² -p shadow, 24-frame series" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/s24.tif" -p shadow --time "$series" -q --overwrite
echo "frame times of the series (renderer frames, --timings):"
"$skylit" shade "$tmp/dem.tif" -o "$tmp/s24.tif" -p shadow --time "$series" -q --overwrite --timings 2>&1 | sed 's/^/  shadow: /'
"$skylit" shade "$tmp/dem.tif" -o "$tmp/f_%02d.png" -p shaded --time "$series" -q --overwrite --timings 2>&1 | sed 's/^/  shaded: /'
time_runs "shade ${size}² -p insolation --time $day (sunrise to sunset, 5 min)" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/ins.tif" -p insolation --time "$day" -q --overwrite
gdalinfo -stats "$tmp/ins.tif" 2>/dev/null | grep -m1 STATISTICS_MEAN | sed "s/^ */  skylit daily mean (Wh\/m2): /"
if command -v grass >/dev/null; then
  grass -c "$tmp/dem.tif" -e "$tmp/grassdb/loc" >/dev/null 2>&1
  grass "$tmp/grassdb/loc/PERMANENT" --exec r.in.gdal input="$tmp/dem.tif" output=dem --q >/dev/null 2>&1
  grass "$tmp/grassdb/loc/PERMANENT" --exec r.slope.aspect elevation=dem slope=slope aspect=aspect --q >/dev/null 2>&1
  n=$ext_runs time_runs "GRASS r.sun mode 2, day 172, step 0.25 h (15 min), 2 threads" \
    grass "$tmp/grassdb/loc/PERMANENT" --exec r.sun elevation=dem aspect=aspect slope=slope day=172 step=0.25 \
    glob_rad=glob nprocs=2 --q --overwrite
  n=$ext_runs time_runs "GRASS r.sun mode 2, day 172, step 0.0833 h (5 min), 2 threads" \
    grass "$tmp/grassdb/loc/PERMANENT" --exec r.sun elevation=dem aspect=aspect slope=slope day=172 step=0.0833333 \
    glob_rad=glob5 nprocs=2 --q --overwrite
  grass "$tmp/grassdb/loc/PERMANENT" --exec r.univar -g glob5 2>/dev/null | grep "^mean=" | sed "s/^/  r.sun daily (Wh\/m2): /"
fi
if command -v saga_cmd >/dev/null; then
  saga_cmd io_gdal 0 -FILES "$tmp/dem.tif" -GRIDS "$tmp/dem_saga" >/dev/null 2>&1 || true
  n=$ext_runs time_runs "SAGA ta_lighting 2 (PISR), one day, step 0.25 h" \
    saga_cmd ta_lighting 2 -GRD_DEM "$tmp/dem_saga.sgrd" -GRD_TOTAL "$tmp/pisr.sgrd" -PERIOD 1 -DAY "$day" -HOUR_STEP 0.25
  n=$ext_runs time_runs "SAGA ta_lighting 2 (PISR), one day, step 0.0833 h (5 min)" \
    saga_cmd ta_lighting 2 -GRD_DEM "$tmp/dem_saga.sgrd" -GRD_TOTAL "$tmp/pisr5.sgrd" -PERIOD 1 -DAY "$day" -HOUR_STEP 0.0833333
  gdalinfo -stats "$tmp/pisr5.sdat" 2>/dev/null | grep -m1 STATISTICS_MEAN | sed "s/^ */  SAGA daily mean (its default units, kWh\/m2): /"
fi
