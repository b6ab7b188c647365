#!/usr/bin/env bash
# Runs the libFuzzer harnesses of tests/fuzz (built with POLARFORM_FUZZ in BUILD_DIR) one after
# the other, each for FUZZ_SECONDS (default 60), or until FUZZ_RUNS executions if that comes
# first, from its seed corpus tests/fuzz/corpus/<harness>/ and dictionary
# tests/fuzz/dict/<harness>.dict. New inputs go to BUILD_DIR/fuzz-corpus/<harness>/ (the
# repository's corpus is only read); a crash, leak, UB report, timeout (> FUZZ_TIMEOUT s, default
# 1) or allocation over FUZZ_MALLOC_MB (default 1024) is saved in BUILD_DIR/fuzz-findings/<harness>/.
# Inputs are at most FUZZ_MAX_LEN bytes (default 8192: every record type and header fits, and
# the rate stays high). Prints executions and coverage per harness (also into FUZZ_SUMMARY, default
# BUILD_DIR/fuzz-summary.txt); exits 1 if anything was found.
#   usage: scripts/fuzz.sh BUILD_DIR [HARNESS...]      (no HARNESS: every harness built)
set -uo pipefail

build=${1:?usage: scripts/fuzz.sh BUILD_DIR [HARNESS...]}
shift
source_dir=$(cd "$(dirname "$0")/.." && pwd)
seconds=${FUZZ_SECONDS:-60}
timeout=${FUZZ_TIMEOUT:-1}
malloc_mb=${FUZZ_MALLOC_MB:-1024}
max_len=${FUZZ_MAX_LEN:-8192}
runs=()
[ -n "${FUZZ_RUNS:-}" ] && runs=(-runs="$FUZZ_RUNS")
summary=${FUZZ_SUMMARY:-$build/fuzz-summary.txt}

harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  for binary in "$build"/tests/fuzz/polarform_fuzz_*; do
    [ -x "$binary" ] && harnesses+=("${binary##*/polarform_fuzz_}")
  done
fi
if [ ${#harnesses[@]} -eq 0 ]; then
  echo "fuzz: no harness in $build/tests/fuzz (build with make fuzz)" >&2
  exit 2
fi

found=0
printf '%-16s %14s %10s %8s %8s  %s\n' harness executions exec/s cov ft findings > "$summary"
for h in "${harnesses[@]}"; do
  binary=$build/tests/fuzz/polarform_fuzz_$h
  [ -x "$binary" ] || { echo "fuzz: no harness $binary" >&2; exit 2; }
  work=$build/fuzz-corpus/$h
  findings=$build/fuzz-findings/$h
  log=$build/fuzz-logs/$h.log
  mkdir -p "$work" "$findings" "$(dirname "$log")"
  dict=()
  [ -f "$source_dir/tests/fuzz/dict/$h.dict" ] && dict=(-dict="$source_dir/tests/fuzz/dict/$h.dict")
  echo "fuzz: $h for ${seconds} s" >&2
  "$binary" "$work" "$source_dir/tests/fuzz/corpus/$h" "${dict[@]}" "${runs[@]}" \
    -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
    -malloc_limit_mb="$malloc_mb" -max_len="$max_len" -print_final_stats=1 \
    -artifact_prefix="$findings/" > "$log" 2>&1
  status=$?
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  artifacts=$(find "$findings" -type f | wc -l)
  if [ "$status" -ne 0 ] || [ "$artifacts" -ne 0 ]; then
    found=1
    echo "fuzz: $h FOUND something (exit $status): see $log and $findings/" >&2
  fi
  printf '%-16s %14s %10s %8s %8s  %s\n' "$h" "${executions:-?}" "${speed:-?}" "${cov:-?}" \
    "${ft:-?}" "$artifacts" >> "$summary"
done
cat "$summary"
if [ "$found" -ne 0 ]; then
  cat >&2 <<MSG
fuzz: findings above. Reproduce one with $build/tests/fuzz/polarform_fuzz_<harness> <file>, fix it,
then keep it as tests/fuzz/corpus/<harness>/regression-<what>.<ext> (replayed by ctest -L fuzz)
and add a unit test that names the case.
MSG
  exit 1
fi
