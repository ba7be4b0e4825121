#!/usr/bin/env bash
# Installs covmap's build and test dependencies from Debian packages. Idempotent: apt-get skips what
# is already installed. Needs root (or sudo).
set -euo pipefail
packages=(
  build-essential cmake
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libeigen3-dev libceres-dev libgeographiclib-dev
  nlohmann-json3-dev libcli11-dev
  # GIS input and output (gis/): GDAL/OGR and PROJ; gdal-bin's tools make the GIS tests' inputs.
  libgdal-dev libproj-dev gdal-bin
  # The HTTP service (service/): cpp-httplib, and SQLite for its job store.
  libcpp-httplib-dev libsqlite3-dev pkg-config
  libgtest-dev libbenchmark-dev
  # The browser tests (tests/browser); fonts-liberation so that text has the same metrics, and the
  # page the same layout, on every machine.
  chromium fonts-liberation
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# The browser tests (tests/browser) run on Node.js >= 18 with npm: Debian 12's nodejs is 18. Asked
# for only when the command is missing, so that a newer Node.js installed otherwise is kept (its own
# npm would conflict with Debian's).
command -v node >/dev/null || missing+=(nodejs)
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
