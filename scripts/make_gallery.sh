#!/usr/bin/env bash
# Makes the pictures of docs/gallery.md: three real DEMs from ../shared/dem, each as
# gdaldem hillshade -multidirectional, skylit shaded (default sky and sun), skylit tinted
# relief, and skylit shaded at a real time under the Preetham sky.
# Usage: scripts/make_gallery.sh [SKYLIT]   (default build/bin/skylit; writes docs/gallery/)
set -euo pipefail
cd "$(dirname "$0")/.."
skylit=${1:-build/bin/skylit}
dem=../shared/dem
out=docs/gallery
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# name, DEM, -srcwin crop, a real time (UTC) with a low sun, gdaldem's scale (gdaldem
# 3.6 needs -s 111120 for degrees; skylit takes the metres from the CRS)
scenes=(
  "tujunga big_tujunga_srtm30_utm11n.tif 300_100_500_400 2026-10-15T16:30Z 1"
  "pyrenees pyrenees_andorra_srtm3_4326.tif 300_350_500_400 2026-12-21T14:30Z 111120"
  "slovenia slovenia_lidar1m_d96tm.tif 250_300_500_400 2026-03-20T16:00Z 1"
)
for scene in "${scenes[@]}"; do
  read -r name file window time scale <<<"$scene"
  crop=$work/$name.tif
  gdal_translate -q -srcwin ${window//_/ } "$dem/$file" "$crop"
  gdaldem hillshade -multidirectional -s "$scale" -q "$crop" "$work/$name.gdal.tif"
  gdal_translate -q -of PNG "$work/$name.gdal.tif" "$out/${name}_gdaldem.png"
  "$skylit" shade "$crop" -p shaded -q --overwrite -o "$out/${name}_shaded.png"
  "$skylit" shade "$crop" -p shaded -q --overwrite --color hypsometric -o "$out/${name}_tinted.png"
  "$skylit" shade "$crop" -p shaded -q --overwrite --sky preetham --time "$time" -o "$out/${name}_time.png"
  echo "$name: $(ls "$out"/${name}_*.png | tr '\n' ' ')"
done
rm -f "$out"/*.aux.xml
