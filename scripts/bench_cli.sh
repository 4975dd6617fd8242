#!/usr/bin/env bash
# End-to-end CLI timing against gdaldem on the same DEM (issue 5's CI-machine target:
# a 1024² `shade -p shaded` at default quality, wall time including I/O, and its ratio
# to `gdaldem hillshade -multidirectional`). Usage: scripts/bench_cli.sh [SIZE] [RUNS]
# after a release build (build/bin/skylit). Prints one line per command: best and
# median wall time over RUNS.
set -euo pipefail
size=${1:-1024}
runs=${2:-3}
here=$(cd "$(dirname "$0")/.." && pwd)
skylit="$here/build/bin/skylit"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$skylit" scene -o "$tmp/dem.tif" --size "$size" -q

. "$here/scripts/bench_common.sh"

print_machine
"$skylit" shade "$tmp/dem.tif" -o "$tmp/probe.tif" -p svf --azimuths 1 2>&1 | tr '\r' '\n' | grep 'computed on' || true
time_runs "skylit shade ${size}² -p shaded (default quality, auto backend)" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/shaded.png" -p shaded -q --overwrite
time_runs "skylit shade ${size}² -p shaded --horizons march" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/march.png" -p shaded --horizons march -q --overwrite
time_runs "skylit shade ${size}² -p shaded --subsample 2 (the march)" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/shaded2.png" -p shaded --subsample 2 -q --overwrite
time_runs "skylit shade ${size}² -p shaded --quality fast" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/fast.png" -p shaded --quality fast -q --overwrite
time_runs "skylit shade ${size}² -p shaded --quality fast --subsample 4 (the march)" \
  "$skylit" shade "$tmp/dem.tif" -o "$tmp/shaded4.png" -p shaded --quality fast --subsample 4 -q --overwrite
time_runs "gdaldem hillshade -multidirectional ${size}² (PNG)" \
  gdaldem hillshade -multidirectional -q -of PNG "$tmp/dem.tif" "$tmp/gd.png"
