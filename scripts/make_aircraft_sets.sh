#!/usr/bin/env bash
# Regenerates the shipped sphere sets data/aircraft/*.json (and the glider picture in
# docs/img/) from the procedural meshes, with fixed seeds: the same build gives the
# same files. Usage: scripts/make_aircraft_sets.sh [path/to/skylit]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
skylit=${1:-$root/build/bin/skylit}
common=(--seed 1 --samples 100000 --error-samples 4000000 --error-rays 400000 --overwrite)
# name:k:radius rule. Winged and rotor sets take the planform rule: their spheres exist
# to cast shadows, and the shell rule gives a thin wing balls of its thickness (the
# solid angle seen from below was 46-90 % short, docs/aircraft.md).
for spec in glider:30:planform light-single:30:planform airliner:30:planform helicopter:30:planform balloon:12:shell; do
  IFS=: read -r name k rule <<<"$spec"
  extra=(--radius "$rule")
  [[ $name == glider ]] && extra+=(--svg "$root/docs/img/aircraft_glider_fit.svg")
  echo "== $name (k = $k)"
  "$skylit" spheres-fit --aircraft "$name" -k "$k" -o "$root/data/aircraft/$name.json" "${common[@]}" "${extra[@]}"
done
