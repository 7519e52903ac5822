#!/usr/bin/env bash
# Instruction counts per benchmark variant (make bench-callgrind), for when wall-clock
# timings are too noisy to compare. Runs each benchmark in --quick mode under
# valgrind --tool=callgrind, collecting only inside bench's timed_runs (the warm-up and
# timed repeats of one bench::measure_ns call) and dumping a profile before each
# measure_ns call, so each non-empty dump holds exactly one measured variant. Prints them
# next to the variant names of the CSV the run wrote (the k-th measurement next to the
# k-th row: right when a benchmark measures once per row, in row order).
# usage: callgrind.sh OUT_DIR BENCH_BINARY...
set -eu
out=$1; shift
mkdir -p "$out"
for bin in "$@"; do
  name=$(basename "$bin")
  prefix="$out/$name.callgrind"
  rm -f "$prefix" "$prefix".*
  valgrind --tool=callgrind --callgrind-out-file="$prefix" --collect-atstart=no \
    --toggle-collect='bench::timed_runs*' --dump-before='bench::measure_ns*' \
    "$bin" --quick --out "$out" >/dev/null 2>"$out/$name.valgrind.log" || {
      echo "$name: valgrind run failed (see $out/$name.valgrind.log)"; continue; }
  echo "== $name (instructions per measure_ns call, warm-up + repeats)"
  csv="$out/$name.csv"
  k=0
  # Numbered dumps in order, then the final one written at exit.
  for dump in $(ls "$prefix".* 2>/dev/null | sort -t. -k3 -n) "$prefix"; do
    ir=$(sed -n 's/^summary: *//p' "$dump" | head -n 1)
    [ -n "$ir" ] && [ "$ir" != "0" ] || continue
    k=$((k + 1))
    variant=""
    if [ -f "$csv" ]; then variant=$(sed -n "$((k + 1))p" "$csv" | cut -d, -f2); fi
    printf '  %3d  %15s  %s\n' "$k" "$ir" "$variant"
  done
done
