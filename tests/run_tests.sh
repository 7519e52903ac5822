#!/usr/bin/env bash
# Runs test binaries and adds up their closing lines "N passed, N failed".
# usage: run_tests.sh plain-binaries... -- sanitized-binaries...
# A binary that dies (signal, sanitizer report, non-zero exit) without reporting a failure
# counts as one failed test. Prints "total: N passed, N failed"; exits non-zero on any failure.
set -u
passed=0; failed=0; phase="plain"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
for bin in "$@"; do
  if [ "$bin" = "--" ]; then phase="asan+ubsan"; continue; fi
  out=$("$bin" 2>&1); rc=$?
  line=$(printf '%s\n' "$out" | grep -E '^[0-9]+ passed, [0-9]+ failed$' | tail -n 1)
  p=0; f=0
  if [ -n "$line" ]; then p=${line%% passed*}; f=${line#*, }; f=${f%% failed*}; fi
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
  if [ "$f" -ne 0 ]; then printf '%s\n' "$out" | tail -n 60; fi
  printf '%-11s %-40s %4d passed, %d failed\n' "$phase" "$(basename "$bin")" "$p" "$f"
  passed=$((passed + p)); failed=$((failed + f))
done
echo "total: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
