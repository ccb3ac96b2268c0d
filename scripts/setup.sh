#!/usr/bin/env bash
# Installs what is missing, and only that: Debian packages (emscripten, Eigen, Chromium, ...) and the
# npm packages of package-lock.json. Safe to run again: it does nothing when all is there.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

APT_PACKAGES=(cmake ninja-build clang-14 g++ libgtest-dev libeigen3-dev nlohmann-json3-dev emscripten chromium)
ensure_debian_packages "${APT_PACKAGES[@]}"
# Chromium's recommended fonts make pages readable in screenshots.
ensure_debian_packages fonts-dejavu-core

# npm ci when node_modules does not match the lockfile (npm keeps a copy of the lock it installed).
lock="$ROOT/package-lock.json"
installed="$ROOT/node_modules/.package-lock.json"
stamp="$ROOT/node_modules/.billow-lock.sha"
want=$(sha256sum "$lock" | cut -d' ' -f1)
if [ ! -f "$installed" ] || [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ]; then
  log "installing npm packages (npm ci)"
  (cd "$ROOT" && npm ci --no-audit --no-fund --loglevel=error)
  echo "$want" >"$stamp"
fi
