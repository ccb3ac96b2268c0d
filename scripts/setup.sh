#!/usr/bin/env bash
# Installs what is missing, and only that: Debian packages (emscripten, Eigen, Chromium, ...) and the
# npm packages of package-lock.json. Safe to run again: it does nothing when all is there.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

APT_PACKAGES=(cmake ninja-build g++ libgtest-dev libeigen3-dev nlohmann-json3-dev emscripten chromium)
missing=()
for p in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  log "installing Debian packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  # Chromium's recommended fonts make pages readable in screenshots.
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq fonts-dejavu-core >/dev/null || true
fi

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
