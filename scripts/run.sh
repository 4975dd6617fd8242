#!/usr/bin/env bash
# Sets up (apt-get), builds, and shades the built-in synthetic scene:
# writes out/default_shaded.png (sky-lit relief) and out/default_skyview.tif.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target skylit
mkdir -p out
build/bin/skylit shade --synthetic -o out/default_shaded.png --product shaded --overwrite
build/bin/skylit shade --synthetic -o out/default_skyview.tif --product skyview --overwrite
echo "wrote out/default_shaded.png and out/default_skyview.tif"
