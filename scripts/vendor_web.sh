#!/usr/bin/env bash
# Vendors the web viewer's libraries from the npm registry into app/tiles/web/ (they are
# committed: the build and `skylit tiles -w leaflet` need no network). Re-run to update;
# the versions are pinned here and in app/tiles/web/LICENSES.md.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
dest="$here/app/tiles/web"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
npm pack --silent leaflet@1.9.4 pmtiles@4.3.0 >/dev/null
for f in leaflet-1.9.4.tgz pmtiles-4.3.0.tgz; do mkdir "${f%.tgz}" && tar xzf "$f" -C "${f%.tgz}" --strip-components 1; done
cp leaflet-1.9.4/dist/leaflet.js leaflet-1.9.4/dist/leaflet.css "$dest/"
cp pmtiles-4.3.0/dist/pmtiles.js "$dest/"
cp leaflet-1.9.4/LICENSE "$dest/LICENSE.leaflet"
echo "vendored leaflet 1.9.4 and pmtiles 4.3.0 into $dest"
