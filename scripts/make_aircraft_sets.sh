#!/usr/bin/env bash
# Regenerates the shipped sphere sets data/aircraft/*.json (and the glider picture in
# docs/img/) from the procedural meshes, with fixed seeds: the same build gives the
# same files. Usage: scripts/make_aircraft_sets.sh [path/to/skylit]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
skylit=${1:-$root/build/bin/skylit}
common=(--seed 1 --samples 100000 --error-samples 4000000 --error-rays 400000 --overwrite)
for spec in glider:30 light-single:30 airliner:30 helicopter:30 balloon:12; do
  name=${spec%%:*} k=${spec##*:}
  extra=()
  [[ $name == glider ]] && extra=(--svg "$root/docs/img/aircraft_glider_fit.svg")
  echo "== $name (k = $k)"
  "$skylit" spheres-fit --aircraft "$name" -k "$k" -o "$root/data/aircraft/$name.json" "${common[@]}" "${extra[@]}"
done
