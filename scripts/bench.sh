#!/usr/bin/env bash
# npm run bench: native and wasm (Node) benchmark figures.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bash "$ROOT/scripts/setup.sh"
bash "$ROOT/scripts/build.sh" native
bash "$ROOT/scripts/build.sh" wasm
log "native"
"$NATIVE_DIR/billow_bench" "$@"
if [ -f "$ROOT/bench/bench-wasm.mjs" ]; then
  log "wasm (node)"
  node "$ROOT/bench/bench-wasm.mjs" "$@"
fi
bash "$ROOT/scripts/build.sh" web >/dev/null && log "site (headless Chromium)" && node "$ROOT/bench/site-bench.mjs"
