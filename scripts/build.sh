#!/usr/bin/env bash
# Installs the Debian and npm packages covmap needs (idempotent) and builds it in build/ (incremental).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-debian.sh
bash scripts/setup-browser-tests.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j"$(nproc)"
