#!/usr/bin/env bash
# Sets up (apt-get), builds and runs the whole test suite: the optimised build,
# then the AddressSanitizer + UndefinedBehaviorSanitizer build.
# Usage: scripts/test.sh [--release-only]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# The browser and PMTiles-reader tests' npm packages, pinned by tests/web/package-lock.json.
npm ci --prefix tests/web --no-audit --no-fund --silent
jobs=$(nproc)

run_preset() {
  echo "== $1: configure, build, test"
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1" -j "$jobs"
  ctest --preset "$1" -j "$jobs"
}

run_preset release
if [ "${1:-}" != "--release-only" ]; then
  run_preset asan
fi
