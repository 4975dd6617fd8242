#!/usr/bin/env bash
# `skylit tiles -p hillshade` (or -p $PRODUCT) against the peer pipeline (gdaldem hillshade
# -compute_edges, then gdal2tiles.py --xyz --processes=2) at zooms native−3 … native
# (10–13 for Big Tujunga, native 13), wall time including I/O; and N shards run one
# after another against one run (the sharding overhead). Usage:
#   scripts/bench_tiles.sh [RUNS] [OLD_SKYLIT] [DEM] [ZOOMS] [SHARDS]
# after a release build; OLD_SKYLIT (optional) is another binary timed the same way
# (e.g. one built from main, for before/after). PRODUCT=shaded (say) times that product
# instead of hillshade; QUICK=1 leaves out the --threads 1 run and the shards. Prints best
# and median per command.
set -euo pipefail
runs=${1:-3}
old=${2:-}
here=$(cd "$(dirname "$0")/.." && pwd)
skylit="$here/build/bin/skylit"
dem=${3:-"$here/../shared/dem/big_tujunga_srtm30_utm11n.tif"}
zooms=${4:-10-13}
shards=${5:-4}
product=${PRODUCT:-hillshade}
[ -f "$dem" ] || { echo "bench_tiles: $dem not found" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

. "$here/scripts/bench_common.sh"

print_machine
echo "dem: $(basename "$dem"), zooms $zooms; $(gdalinfo --version); $("$skylit" --version)"
time_runs "gdaldem hillshade -compute_edges + gdal2tiles.py --xyz --processes=2" \
  bash -c "rm -rf '$tmp/g2t' && gdaldem hillshade -compute_edges -q '$dem' '$tmp/hs.tif' &&
           gdal2tiles.py --xyz --processes=2 -q -z $zooms '$tmp/hs.tif' '$tmp/g2t'"
time_runs "skylit tiles -p $product (this build)" \
  "$skylit" tiles "$dem" -o "$tmp/new.pmtiles" -p $product --zoom "$zooms" --overwrite -q
[ -n "${QUICK:-}" ] || time_runs "skylit tiles -p $product --threads 1 (this build)" \
  "$skylit" tiles "$dem" -o "$tmp/new1.pmtiles" -p $product --zoom "$zooms" --overwrite -q --threads 1
if [ -n "$old" ]; then
  time_runs "skylit tiles -p $product ($old)" \
    "$old" tiles "$dem" -o "$tmp/old.pmtiles" -p $product --zoom "$zooms" --overwrite -q
fi
if [ -z "${QUICK:-}" ]; then
  time_runs "$shards shards in sequence (this build)" \
    bash -c "for i in \$(seq 1 $shards); do '$skylit' tiles '$dem' -o '$tmp/s'\$i.pmtiles -p $product \
               --zoom $zooms --shard \$i/$shards --overwrite -q || exit 1; done"
  "$skylit" tiles merge "$tmp"/s*.pmtiles -o "$tmp/m.pmtiles" -q
  cmp -s "$tmp/m.pmtiles" "$tmp/new.pmtiles" && echo "the shards merged equal the single run byte for byte" ||
    echo "the shards merged DIFFER from the single run"
fi
echo "gdal2tiles wrote $(find "$tmp/g2t" -name '*.png' | wc -l) PNGs"
