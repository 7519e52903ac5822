#!/usr/bin/env bash
# Runs test binaries and adds up their closing lines "N passed, N failed".
# usage: run_tests.sh plain-binaries... -- sanitized-binaries...
# The binaries run TEST_JOBS at a time (default: one per core; they share no files: each
# test writes under its own temporary folder); their results are printed in the order given.
# A binary that dies (signal, sanitizer report, non-zero exit) without reporting a failure
# counts as one failed test. Prints "total: N passed, N failed"; exits non-zero on any failure.
set -u
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
jobs=${TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

# Runs the i-th binary: its output to $results/i.out, its exit code to $results/i.rc.
run_one() { "$2" > "$results/$1.out" 2>&1; echo $? > "$results/$1.rc"; }

bins=(); phases=(); phase="plain"
for bin in "$@"; do
  if [ "$bin" = "--" ]; then phase="asan+ubsan"; continue; fi
  bins+=("$bin"); phases+=("$phase")
done
running=0
for i in "${!bins[@]}"; do
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
  run_one "$i" "${bins[$i]}" &
  running=$((running + 1))
done
wait

passed=0; failed=0
for i in "${!bins[@]}"; do
  out=$(cat "$results/$i.out"); rc=$(cat "$results/$i.rc")
  line=$(printf '%s\n' "$out" | grep -E '^[0-9]+ passed, [0-9]+ failed$' | tail -n 1)
  p=0; f=0
  if [ -n "$line" ]; then p=${line%% passed*}; f=${line#*, }; f=${f%% failed*}; fi
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  if [ "$f" -ne 0 ]; then printf '%s\n' "$out" | tail -n 60; fi
  printf '%-11s %-40s %4d passed, %d failed\n' "${phases[$i]}" "$(basename "${bins[$i]}")" "$p" "$f"
  passed=$((passed + p)); failed=$((failed + f))
done
echo "total: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
