#!/usr/bin/env bash
# Installs the browser tests' npm packages (tests/browser/package-lock.json: playwright-core) into
# tests/browser/node_modules. Idempotent: runs `npm ci` only when node_modules is missing or was
# installed from another lockfile. Needs node and npm (scripts/setup-debian.sh); Chromium itself is
# Debian's package, so no browser is downloaded.
set -euo pipefail
cd "$(dirname "$0")/../tests/browser"
stamp=node_modules/.covmap-installed-lock.json
if cmp -s package-lock.json "$stamp"; then
  echo "setup: browser test packages present"
  exit 0
fi
PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error
cp package-lock.json "$stamp"
