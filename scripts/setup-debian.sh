#!/usr/bin/env bash
# Installs covmap's build dependencies from Debian packages. Idempotent: apt-get skips what is
# already installed. Needs root (or sudo).
set -euo pipefail
packages=(
  build-essential cmake
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libeigen3-dev libceres-dev libgeographiclib-dev
  nlohmann-json3-dev libcli11-dev
  libgtest-dev libbenchmark-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
