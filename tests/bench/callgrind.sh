#!/usr/bin/env bash
# Instruction counts per benchmark variant (make bench-callgrind), for when wall-clock
# timings are too noisy to compare. Runs each benchmark in --quick mode under
# valgrind --tool=callgrind, collecting only inside bench::measure_ns and dumping a
# profile after each call of it, so dump k holds the instructions of the k-th measured
# variant (warm-up + repeats). Prints them next to the variant names of the CSV the run
# wrote (rows in the order the benchmark measured them, when it measures one per row).
# usage: callgrind.sh OUT_DIR BENCH_BINARY...
set -eu
out=$1; shift
mkdir -p "$out"
for bin in "$@"; do
  name=$(basename "$bin")
  prefix="$out/$name.callgrind"
  rm -f "$prefix".*
  valgrind --tool=callgrind --callgrind-out-file="$prefix.%p" --collect-atstart=no \
    --toggle-collect='bench::measure_ns*' --dump-after='bench::measure_ns*' \
    "$bin" --quick --out "$out" >/dev/null 2>"$out/$name.valgrind.log" || {
      echo "$name: valgrind run failed (see $out/$name.valgrind.log)"; continue; }
  echo "== $name (instructions per measure_ns call, warm-up + repeats)"
  csv="$out/$name.csv"
  k=0
  for dump in $(ls "$prefix".* 2>/dev/null | sort -t. -k4 -n); do
    ir=$(sed -n 's/^summary: *//p' "$dump" | head -n 1)
    [ -n "$ir" ] && [ "$ir" != "0" ] || continue
    k=$((k + 1))
    variant=""
    if [ -f "$csv" ]; then variant=$(sed -n "$((k + 1))p" "$csv" | cut -d, -f2); fi
    printf '  %3d  %15s  %s\n' "$k" "$ir" "$variant"
  done
done
