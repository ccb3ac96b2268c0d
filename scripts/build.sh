#!/usr/bin/env bash
# Builds everything that changed: the native library, CLI and tests (build/native), the wasm module and
# the wasm tests (build/wasm), and the static site (web/dist). Incremental: ninja rebuilds only what changed.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
what="${1:-all}"   # all | native | wasm | web

build_native() {
  native_compilers
  # A build folder configured with another compiler (g++ before) is configured again from scratch.
  if [ -f "$NATIVE_DIR/CMakeCache.txt" ] && ! grep -q "^CMAKE_CXX_COMPILER:[A-Z]*=$CXX_BIN$" "$NATIVE_DIR/CMakeCache.txt"; then
    log "configuring build/native again for $CXX_BIN"
    rm -rf "$NATIVE_DIR"
  fi
  [ -f "$NATIVE_DIR/build.ninja" ] || CC="$CC_BIN" CXX="$CXX_BIN" cmake -S "$ROOT" -B "$NATIVE_DIR" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release >/dev/null
  log "building native (build/native)"
  cmake --build "$NATIVE_DIR" -j"$(nproc)" >"$ROOT/build/native-build.log" 2>&1 || { cat "$ROOT/build/native-build.log" >&2; die "the native build failed (log above)"; }
  test -x "$NATIVE_DIR/billow" || die "the native build failed"
}

build_wasm() {
  if [ ! -f "$WASM_DIR/build.ninja" ]; then
    # Our own emulator: emcmake's default passes a flag node 20 refuses (TOOLCHAIN P3).
    emcmake cmake -S "$ROOT" -B "$WASM_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      "-DCMAKE_CROSSCOMPILING_EMULATOR=/usr/bin/node;--no-experimental-fetch" >/dev/null
  fi
  log "building wasm (build/wasm)"
  cmake --build "$WASM_DIR" -j"$(nproc)" >"$ROOT/build/wasm-build.log" 2>&1 || { cat "$ROOT/build/wasm-build.log" >&2; die "the wasm build failed (log above)"; }
  test -f "$WASM_DIR/billow.wasm" -a -f "$WASM_DIR/billow.mjs" || die "the wasm build failed"
}

build_web() {
  local dist="${BILLOW_DIST:-$ROOT/web/dist}" # BILLOW_DIST: build the site elsewhere (a second checkout's tests)
  log "building the web app ($dist)"
  (cd "$ROOT" && npx vite build web --logLevel warn)
  node "$ROOT/scripts/site-report.mjs" "$dist" # bundle sizes, raw and gzipped
}

case "$what" in
  native) build_native ;;
  wasm) build_wasm ;;
  web) build_web ;;
  all) build_native; build_wasm; build_web ;;
  *) die "usage: build.sh [all|native|wasm|web]" ;;
esac
