#!/usr/bin/env bash
# Runs every libFuzzer target for a fixed time and summarises libFuzzer's final figures.
# usage: run_fuzz.sh BUILD SECONDS fuzz-binaries...      (called by `make fuzz`)
# Target $BUILD/fuzz/fuzz_NAME starts from the seed corpus tests/fuzz/corpus/NAME, the kept
# crash inputs tests/fuzz/regressions/NAME and, where there is one, the corpus a long run
# grew tests/fuzz/found/NAME, with the dictionary tests/fuzz/NAME.dict;
# new interesting inputs go to $BUILD/fuzz/corpus/NAME, crashes to $BUILD/fuzz/artifacts/NAME/.
# Writes $BUILD/fuzz/summary.txt (one line per target: executions, cov, ft, corpus, crashes)
# and exits non-zero if any target crashed.
set -u
build=$1; seconds=$2; shift 2
summary="$build/fuzz/summary.txt"
: > "$summary"
status=0
for bin in "$@"; do
  name=$(basename "$bin"); name=${name#fuzz_}
  work="$build/fuzz/corpus/$name"; artifacts="$build/fuzz/artifacts/$name"; log="$build/fuzz/$name.log"
  mkdir -p "$work" "$artifacts"
  dict=(); [ -f "tests/fuzz/$name.dict" ] && dict=(-dict="tests/fuzz/$name.dict")
  found=(); [ -d "tests/fuzz/found/$name" ] && found=("tests/fuzz/found/$name")
  echo "fuzz: $name for ${seconds}s (log $log)"
  "$bin" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
         -artifact_prefix="$artifacts/" "${dict[@]}" "$work" "tests/fuzz/corpus/$name" "tests/fuzz/regressions/$name" "${found[@]}" \
         > "$log" 2>&1
  rc=$?
  execs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' | tail -n 1)
  final=$(grep -E '^#[0-9]+.*(DONE|cov:)' "$log" | tail -n 1)
  cov=$(printf '%s\n' "$final" | sed -nE 's/.*cov: ([0-9]+).*/\1/p')
  ft=$(printf '%s\n' "$final" | sed -nE 's/.*ft: ([0-9]+).*/\1/p')
  corp=$(printf '%s\n' "$final" | sed -nE 's/.*corp: ([0-9]+).*/\1/p')
  crashes=$(find "$artifacts" -type f | wc -l)
  line=$(printf '%-4s seconds=%s executions=%s cov=%s ft=%s corpus=%s crashes=%s exit=%s' \
         "$name" "$seconds" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$crashes" "$rc")
  echo "$line" | tee -a "$summary"
  if [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ]; then
    status=1
    grep -E 'ERROR|fuzz check failed|SUMMARY|Test unit written' "$log" | head -n 5
  fi
done
exit $status
