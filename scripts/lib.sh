# Shared by the scripts: paths, logging, and the environment the toolchain needs (TOOLCHAIN.md).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"  # em++ needs Debian's acorn with NodeSource node (P1)
NATIVE_DIR="$ROOT/build/native"
WASM_DIR="$ROOT/build/wasm"
log() { printf '\033[1;34m[billow]\033[0m %s\n' "$*" >&2; }
die() { printf '\033[1;31m[billow]\033[0m %s\n' "$*" >&2; exit 1; }

# Installs the Debian packages among "$@" that are not installed yet (apt-get update only when needed).
ensure_debian_packages() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  log "installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# The native and fuzz builds' compiler: Debian's clang 14, the LLVM the wasm build's em++ uses too. On this code it
# compiles the native build a quarter faster than g++ 12, and its binaries run as fast or faster (bench/README.md).
native_compilers() {
  ensure_debian_packages clang-14
  CC_BIN=$(command -v clang || command -v clang-14) || die "clang not found"
  CXX_BIN=$(command -v clang++ || command -v clang++-14) || die "clang++ not found"
}
