#!/usr/bin/env bash
# Installs every system dependency of skylit from Debian 12 packages.
# Idempotent: packages already present are skipped; uses sudo when not root.
# --upgrade also brings the installed ones, and the installed packages they depend on,
# up to the current Debian 12 update, as a fresh install would get them (.ci/run: CI
# tests what users install, not the image's older packages; GDAL's libpng, Mesa's LLVM).
# Usage: scripts/setup.sh [--upgrade]
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libgdal-dev gdal-bin libgeographiclib-dev
  libglfw3-dev libglm-dev libopenimageio-dev openimageio-tools
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev
  libpugixml-dev libproj-dev proj-data
  libsqlite3-dev zlib1g-dev sqlite3   # tiles/: MBTiles, PMTiles staging, gzip; sqlite3 CLI for tests
  clang-16 libclang-rt-16-dev   # libFuzzer for scripts/fuzz.sh (the build itself uses g++)
  chromium                      # headless browser for the tile viewer's test (tests/web)
  ffmpeg                        # skylit render: video encoding (frames piped to it)
  libimgui-dev                  # skylit-view's panel (Dear ImGui with its GLFW and OpenGL 3 backends)
  xvfb xauth                    # the viewer's window tests (xvfb-run)
)
# tests/web runs on node + npm: Debian's, unless a node is installed already (NodeSource's
# nodejs ships its own npm and conflicts with Debian's npm package).
command -v npm >/dev/null 2>&1 || PACKAGES+=(nodejs npm)
upgrade=false
case "${1:-}" in
  "") ;;
  --upgrade) upgrade=true ;;
  *) echo "usage: $0 [--upgrade]" >&2; exit 2 ;;
esac

# "name version" of each listed package that is installed (dpkg-query fails when any
# package is unknown to dpkg, as on a fresh machine: its partial list is still right).
installed() {
  { dpkg-query -W -f='${Package} ${Version} ${Status}\n' "${PACKAGES[@]}" 2>/dev/null || true; } |
    awk '$NF == "installed" { print $1, $2 }'
}

before=$(installed)
missing=()
for p in "${PACKAGES[@]}"; do
  grep -q "^$p " <<<"$before" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ] && ! $upgrade; then
  echo "setup: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The installed packages the listed ones depend on, directly or not, that have an update.
upgradable_dependencies() {
  comm -12 \
    <(apt-cache depends --recurse --installed --no-recommends --no-suggests --no-conflicts --no-breaks \
        --no-replaces --no-enhances "${PACKAGES[@]}" 2>/dev/null | grep -v '^ ' | grep -v '^<' | sed 's/:.*//' | sort -u) \
    <(apt list --upgradable 2>/dev/null | grep / | cut -d/ -f1 | sort -u)
}
if $upgrade; then
  $SUDO apt-get install -y -qq --only-upgrade "${PACKAGES[@]}" >/dev/null
  mapfile -t dependencies < <(upgradable_dependencies)
  if [ ${#dependencies[@]} -gt 0 ]; then
    echo "setup: upgrading ${#dependencies[@]} installed dependencies: ${dependencies[*]}"
    $SUDO apt-get install -y -qq --only-upgrade "${dependencies[@]}" >/dev/null
  fi
  changed=$(join <(sort <<<"$before") <(installed | sort) | awk '$2 != $3 { print $1, $2, "->", $3 }')
  if [ -n "$changed" ]; then
    echo "setup: upgraded:"
    echo "$changed" | sed 's/^/  /'
  else
    echo "setup: all ${#PACKAGES[@]} packages up to date"
  fi
fi
