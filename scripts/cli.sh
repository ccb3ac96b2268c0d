#!/usr/bin/env bash
# npm run cli -- ARGS: builds the native tool if needed and runs build/native/billow ARGS.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
if [ ! -x "$NATIVE_DIR/billow" ]; then
  bash "$ROOT/scripts/setup.sh"
fi
bash "$ROOT/scripts/build.sh" native >/dev/null 2>&1 || bash "$ROOT/scripts/build.sh" native
exec "$NATIVE_DIR/billow" "$@"
