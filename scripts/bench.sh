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
# Pattern optimization (the paper's Table 1): BILLOW_BENCH_DESIGNS=sphere3,teddy picks designs.
designs=()
[ -n "${BILLOW_BENCH_DESIGNS:-}" ] && designs=(--designs "$BILLOW_BENCH_DESIGNS")
mkdir -p "$ROOT/build/bench"
log "pattern optimization, native"
"$NATIVE_DIR/billow_design_bench" "${designs[@]}" --json-out "$ROOT/build/bench/design-native.json"
log "pattern optimization, wasm (node)"
node "$ROOT/bench/design-bench-wasm.mjs" "${designs[@]}" --json-out "$ROOT/build/bench/design-wasm.json"
log "the paper's Table 1 beside Billow's runs"
node "$ROOT/bench/table1.mjs" "$ROOT/build/bench/design-native.json" "$ROOT/build/bench/design-wasm.json"
# Suggested seam layouts (bench/README.md "Suggested seam layouts"): three meshes at 12 panels; the whole table with
# node bench/suggest-bench.mjs.
log "suggested seam layouts, native"
node "$ROOT/bench/suggest-bench.mjs" --panels 12 --meshes koala,spot,blub
log "suggested seam layouts, wasm (node)"
node --no-experimental-fetch "$ROOT/bench/suggest-bench-wasm.mjs" --panels 12 --meshes koala,spot,blub
bash "$ROOT/scripts/build.sh" web >/dev/null && log "site (headless Chromium)" && node "$ROOT/bench/site-bench.mjs"
log "suggested seam layouts, the app (headless Chromium)"
node "$ROOT/bench/suggest-bench-app.mjs" --panels 12 --meshes koala
