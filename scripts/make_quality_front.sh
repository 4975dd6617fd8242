#!/usr/bin/env bash
# Remakes data/quality/front.csv, the speed/error front of `skylit shade --max-error`:
# `skylit bench --front` over the synthetic scene and crops of two projected real DEMs
# from ../shared/dem (the sweep needs a projected grid). SIZE (default 96) is the side
# of every scene; about 5 minutes on 2 shared cores at 96.
set -euo pipefail
cd "$(dirname "$0")/.."
SIZE=${SIZE:-96}
DEM=${DEM:-../shared/dem}
SKYLIT=${SKYLIT:-build/bin/skylit}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
gdal_translate -q -srcwin 400 400 "$SIZE" "$SIZE" "$DEM/big_tujunga_srtm30_utm11n.tif" "$tmp/big_tujunga_crop.tif"
gdal_translate -q -srcwin 300 300 "$SIZE" "$SIZE" "$DEM/slovenia_lidar1m_d96tm.tif" "$tmp/slovenia_crop.tif"
"$SKYLIT" bench "$tmp/big_tujunga_crop.tif" "$tmp/slovenia_crop.tif" --with-synthetic --sizes "$SIZE" \
  --sweep default --backend reference --clock cpu --runs 2 --warmup 1 --front data/quality/front.csv "$@"
