#!/usr/bin/env bash
# libFuzzer + ASan + UBSan on the input readers (tests/fuzz). Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] (60)
# Installs clang 14 and its runtime when missing, builds build/fuzz, runs every target for the given time on
# its seed corpus (tests/fuzz/corpus/<target>, read only; new inputs go to build/fuzz/corpus/<target>) and
# prints executions, coverage and crashes per target. Crash inputs are left in build/fuzz/artifacts/<target>/.
# Exits non-zero when any target crashed. FUZZ_TARGETS="obj stl" restricts the run; FUZZ_JOBS sets how many
# targets run at once (default: the number of CPUs); FUZZ_BUILD_DIR moves the build (default build/fuzz).
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

SECONDS_PER_TARGET="${1:-60}"
[[ "$SECONDS_PER_TARGET" =~ ^[0-9]+$ ]] || die "usage: scripts/fuzz.sh [SECONDS_PER_TARGET]"
TARGETS=(${FUZZ_TARGETS:-obj stl ply off pattern_json design_json})
FUZZ_DIR="${FUZZ_BUILD_DIR:-$ROOT/build/fuzz}"
FUZZ_JOBS="${FUZZ_JOBS:-$(nproc)}"

ensure_debian_packages libclang-rt-14-dev cmake ninja-build libeigen3-dev nlohmann-json3-dev libgtest-dev
native_compilers

log "building the fuzz targets in $FUZZ_DIR"
if [ ! -f "$FUZZ_DIR/build.ninja" ]; then
  CC="$CC_BIN" CXX="$CXX_BIN" cmake -S "$ROOT" -B "$FUZZ_DIR" -G Ninja -DBILLOW_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$FUZZ_DIR" --target billow_fuzz >/dev/null

max_len() {
  case "$1" in
    obj | stl | ply | off) echo 8192 ;;
    *) echo 16384 ;;
  esac
}
dict_of() {
  case "$1" in
    obj | stl | ply | off) echo "$ROOT/tests/fuzz/$1.dict" ;;
    *) echo "$ROOT/tests/fuzz/json.dict" ;;
  esac
}

run_target() {
  local t="$1" work="$FUZZ_DIR/corpus/$1" art="$FUZZ_DIR/artifacts/$1"
  mkdir -p "$work" "$art"
  rm -f "$art"/crash-* "$art"/leak-* "$art"/timeout-* "$art"/oom-*
  # -timeout: one input taking over 10 s is a hang; -rss_limit_mb: a reader trying to allocate beyond its
  # limits is a finding. halt_on_error: a UBSan report fails the run like an ASan one.
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=detect_leaks=1 \
    "$FUZZ_DIR/tests/fuzz/fuzz_$t" "$work" "$ROOT/tests/fuzz/corpus/$t" \
    -max_total_time="$SECONDS_PER_TARGET" -max_len="$(max_len "$t")" -dict="$(dict_of "$t")" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$art/" \
    >"$FUZZ_DIR/fuzz_$t.log" 2>&1 || true
}

log "fuzzing ${TARGETS[*]} for ${SECONDS_PER_TARGET}s each, $FUZZ_JOBS at a time"
running=0
for t in "${TARGETS[@]}"; do
  run_target "$t" &
  running=$((running + 1))
  if ((running >= FUZZ_JOBS)); then
    wait -n || true
    running=$((running - 1))
  fi
done
wait

status=0
printf '%-14s %12s %8s %8s %8s %8s\n' target executions exec/s cov corpus crashes
for t in "${TARGETS[@]}"; do
  logf="$FUZZ_DIR/fuzz_$t.log"
  execs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$logf" | grep -oE '[0-9]+$' || true)
  speed=$(grep -oE 'stat::average_exec_per_sec: *[0-9]+' "$logf" | grep -oE '[0-9]+$' || true)
  cov=$(grep -oE 'cov: [0-9]+' "$logf" | tail -1 | grep -oE '[0-9]+' || true)
  corpus=$(grep -oE 'corp: [0-9]+' "$logf" | tail -1 | grep -oE '[0-9]+' || true)
  crashes=$(find "$FUZZ_DIR/artifacts/$t" -type f | wc -l)
  if ((crashes)) || grep -qE 'ERROR: (libFuzzer|AddressSanitizer)|runtime error:' "$logf"; then
    status=1
    ((crashes)) || crashes="?"
  elif [ -z "$execs" ]; then
    status=1  # it never ran (a dictionary it could not parse, a build that failed): see its log
    crashes="-"
  fi
  printf '%-14s %12s %8s %8s %8s %8s\n' "$t" "${execs:--}" "${speed:--}" "${cov:--}" "${corpus:--}" "$crashes"
done
if ((status)); then
  log "crashes, or a target that did not run: see build/fuzz/fuzz_<target>.log and build/fuzz/artifacts/<target>/ (replay: build/fuzz/tests/fuzz/fuzz_<target> <file>)"
fi
exit "$status"
