#!/usr/bin/env bash
# Sphere blockers end to end, one sitting (issue 14's speed targets): `shade -p shaded`
# and `-p shadow` over a SIZE² DEM of 1 m texels (the built-in scene rescaled to 60 m of
# relief) with no aircraft, one and ten 30-sphere airliners (data/aircraft/airliner.json)
# ~150 m above the ground, on BACKEND (gpu: the GLSL path, llvmpipe without a GPU;
# reference: the CPU), against gdaldem hillshade; and a `shadow` replay of the sample
# glider track. Usage: [PRODUCTS="shaded shadow" (empty: the replay alone)] [NO_REPLAY=1] [WORK=DIR] scripts/bench_blockers.sh [SIZE] [RUNS] [BACKEND] after a release
# build. Prints best and median wall time over RUNS per command, and for the aircraft the
# median over rounds of the ratio to no aircraft in the same round.
set -euo pipefail
size=${1:-1024}
runs=${2:-3}
backend=${3:-gpu}
here=$(cd "$(dirname "$0")/.." && pwd)
skylit="$here/build/bin/skylit"
if [ -n "${WORK:-}" ]; then  # keep the DEM and sphere files there
  tmp=$WORK
  mkdir -p "$tmp"
else
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
fi
"$skylit" scene -o "$tmp/scene.tif" --size "$size" -q
# 1 m texels, heights 400–460 m, the origin kept (UTM 32N 400000 E, 5200000 N).
gdal_translate -q -scale 400 2200 400 460 -ot Float32 -a_ullr 400000 5200000 $((400000 + size)) $((5200000 - size)) \
  "$tmp/scene.tif" "$tmp/dem.tif"

python3 - "$here/data/aircraft/airliner.json" "$tmp" "$size" <<'PY'
import json, sys
spheres = json.load(open(sys.argv[1]))["spheres"]
out, size = sys.argv[2], int(sys.argv[3])
def write(name, centres):
    with open(f"{out}/{name}.csv", "w") as f:
        f.write("x,y,z,radius\n")
        for (x, y, z) in centres:
            for s in spheres:
                c = s["centre"]
                f.write(f"{x + c[0]:.3f},{y + c[1]:.3f},{z + c[2]:.3f},{s['radius']}\n")
mid = size / 2
write("one", [(400000 + mid, 5200000 - mid, 610)])
write("ten", [(400000 + mid * (0.4 + 0.12 * k), 5200000 - mid * (0.5 + 0.1 * (k % 4)), 600 + 5 * k) for k in range(10)])
PY

. "$here/scripts/bench_common.sh"

print_machine
"$skylit" shade "$tmp/dem.tif" -o "$tmp/probe.tif" -p shaded --backend "$backend" --spheres "$tmp/one.csv" 2>&1 |
  tr '\r' '\n' | grep 'computed on' || true
time_runs "gdaldem hillshade ${size}²" gdaldem hillshade -q "$tmp/dem.tif" "$tmp/gd.tif"
sun=(--sun-azimuth 200 --sun-elevation 35)
# The three cases in turn, RUNS rounds: on a noisy machine the ratio within a round,
# then its median over the rounds, is steadier than ratios of separate bests.
for p in ${PRODUCTS-shaded shadow}; do
  log="$tmp/times_$p.txt"
  : >"$log"
  for ((r = 0; r < runs; ++r)); do
    for a in none one ten; do
      spheres=()
      [ "$a" = none ] || spheres=(--spheres "$tmp/$a.csv")
      t0=$(date +%s.%N)
      "$skylit" shade "$tmp/dem.tif" -p "$p" "${sun[@]}" "${spheres[@]}" --backend "$backend" --overwrite \
        -o "$tmp/out.tif" -q || { echo "$p, aircraft: $a: FAILED"; exit 1; }
      t1=$(date +%s.%N)
      echo "$r $a $(echo "$t1 - $t0" | bc)" >>"$log"
    done
  done
  python3 - "$log" "$p" "$backend" <<'PY'
import collections, statistics, sys
rounds = collections.defaultdict(dict)
for line in open(sys.argv[1]):
    r, a, t = line.split()
    rounds[r][a] = float(t)
for a in ("none", "one", "ten"):
    ts = [x[a] for x in rounds.values()]
    ratio = "" if a == "none" else "  median ratio to none %.2fx" % statistics.median(x[a] / x["none"] for x in rounds.values())
    print("%-64s best %7.2f s  median %7.2f s%s" % (f"{sys.argv[2]}, aircraft: {a} ({sys.argv[3]})", min(ts), statistics.median(ts), ratio))
PY
done
[ -n "${NO_REPLAY:-}" ] && exit 0
# Replay: 61 shadow frames (1 s) of the sample glider over the built-in scene (30 m texels).
replay=(--time 2026-06-21T10:00:00Z/2026-06-21T10:01:00Z/PT1S --backend "$backend" --overwrite)
time_runs "shadow replay, 61 frames, no track ($backend)" "$skylit" shade "$tmp/scene.tif" -p shadow "${replay[@]}" \
  -o "$tmp/frames_%03d.tif"
time_runs "shadow replay, 61 frames, airliner on the track ($backend)" "$skylit" shade "$tmp/scene.tif" -p shadow \
  "${replay[@]}" --track "$here/data/tracks/sample_glider.igc" --aircraft airliner -o "$tmp/frames_%03d.tif"
time_runs "the same, the sun swept every frame (--sun-tolerance 0)" "$skylit" shade "$tmp/scene.tif" -p shadow \
  "${replay[@]}" --track "$here/data/tracks/sample_glider.igc" --aircraft airliner --sun-tolerance 0 \
  -o "$tmp/frames_%03d.tif"
