# Shared by the scripts: paths, logging, and the environment the toolchain needs (TOOLCHAIN.md).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"  # em++ needs Debian's acorn with NodeSource node (P1)
NATIVE_DIR="$ROOT/build/native"
WASM_DIR="$ROOT/build/wasm"
log() { printf '\033[1;34m[billow]\033[0m %s\n' "$*" >&2; }
die() { printf '\033[1;31m[billow]\033[0m %s\n' "$*" >&2; exit 1; }
