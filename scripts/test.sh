#!/usr/bin/env bash
# npm test: install what is missing, build, then run every suite: native GoogleTest (ctest), the same
# GoogleTest suite compiled to wasm (ctest under node), the wasm module through the JS layer in Node
# (node:test), the app end to end in headless Chromium (node:test + playwright-core), and a short
# libFuzzer run of the readers under ASan/UBSan.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
bash "$ROOT/scripts/setup.sh"
bash "$ROOT/scripts/build.sh" all

passed=0
failed=0
status=0
out="$ROOT/build/test-logs"
mkdir -p "$out"

# Runs a suite, shows its output, and adds its counts (parsed with the given kind) to the totals.
suite() {
  local name="$1" kind="$2"
  shift 2
  log "suite: $name"
  local log_file="$out/$name.log" rc=0
  "$@" 2>&1 | tee "$log_file" || rc=$?
  [ "$rc" -eq 0 ] || status=1
  local p=0 f=0
  if [ "$kind" = exit ]; then
    if [ "$rc" -eq 0 ]; then p=1; else f=1; fi
  elif [ "$kind" = ctest ]; then
    local line
    line=$(grep -E 'tests passed, [0-9]+ tests failed out of [0-9]+' "$log_file" | tail -1 || true)
    if [ -n "$line" ]; then
      f=$(sed -E 's/.* ([0-9]+) tests failed out of ([0-9]+).*/\1/' <<<"$line")
      p=$(( $(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$line") - f ))
    fi
  elif [ "$kind" = gtest-shards ]; then
    # ctest ran GoogleTest shards: count their tests from the shards' output, which ctest keeps whole.
    local shards_log="$WASM_DIR/Testing/Temporary/LastTest.log"
    p=$(awk '/^\[  PASSED  \] [0-9]+ tests?\./ {s += $4} END {print s + 0}' "$shards_log")
    f=$(awk '/^\[  FAILED  \] [0-9]+ tests?, listed below/ {s += $4} END {print s + 0}' "$shards_log")
  else
    p=$(grep -E '^# pass [0-9]+' "$log_file" | tail -1 | awk '{print $3}')
    f=$(grep -E '^# fail [0-9]+' "$log_file" | tail -1 | awk '{print $3}')
  fi
  p=${p:-0}; f=${f:-0}
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi  # a crashed runner counts as a failure
  passed=$((passed + p)); failed=$((failed + f))
  log "$name: $p passed, $f failed"
}

suite native ctest ctest --test-dir "$NATIVE_DIR" --output-on-failure -j2
suite wasm gtest-shards ctest --test-dir "$WASM_DIR" --output-on-failure -j2
# Two files at a time in both suites (node's default on two cores is one): a file mostly waits on one
# solver thread and, in the browser, on the page, so a second file fills the other core.
suite node node node --test --test-concurrency=2 --test-timeout=120000 "$ROOT/tests/node/"
# The timeout is per file as well as per test: the suggestion file optimizes the octopus's layout at the
# design's size (100 s alone, over 200 s with another file beside it).
suite e2e node node --test --test-concurrency=2 --test-timeout=900000 "$ROOT/tests/e2e/"
# A short libFuzzer run of every reader under ASan+UBSan (npm run fuzz runs longer): counts as one test.
suite fuzz exit bash "$ROOT/scripts/fuzz.sh" "${BILLOW_FUZZ_SECONDS:-5}"

echo
echo "all suites: $passed passed, $failed failed"
exit $status
