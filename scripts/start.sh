#!/usr/bin/env bash
# npm start: install what is missing, build what changed, serve the app and print its URL.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bash "$ROOT/scripts/setup.sh"
bash "$ROOT/scripts/build.sh" all
PORT="${PORT:-5173}"
log "Billow is at http://localhost:$PORT/  (Ctrl+C stops it)"
cd "$ROOT" && exec npx vite preview web --port "$PORT" --strictPort --host 127.0.0.1
