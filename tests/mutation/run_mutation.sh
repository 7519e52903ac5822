#!/usr/bin/env bash
# The project's own mutation check (`make mutation`; not part of `make test`).
# usage: run_mutation.sh [BUILD] [MUTANT_LIST] [ID_FILTER]
#   BUILD        build folder (default build); everything goes under BUILD/mutation/
#   MUTANT_LIST  default tests/mutation/mutants.txt (format described there)
#   ID_FILTER    run only the mutants whose id matches this extended regular expression
#
# The working tree is never modified. Its files (tracked and untracked, not ignored) are
# copied into BUILD/mutation/tree (only the files that differ, so a second run reuses the
# first one's objects; a first run starts from BUILD's own objects), where the library and
# the test programs the mutants name are built once, plain -O2 without sanitizers, and
# must pass. Then, per mutant: the one substitution is applied to the copy (its text must
# occur exactly once in the file), make rebuilds only the objects that depend on that
# file, the library and the named test programs, and those run (each under a timeout)
# until one fails: the mutant is KILLED (by that test, or by the timeout), else it
# SURVIVED. The file and the objects built from it are then put back as they were. A
# mutant whose text is not found once, or that does not compile, is INVALID (a stale
# list: fix it).
#
# Prints one row per mutant and a closing line; writes BUILD/mutation/report.txt. Exits
# non-zero when fewer than MUTATION_MIN_KILLED % (default 90) are killed, when a mutant
# is invalid, or when a surviving mutant's id is not named in documentation/reliability.md
# (each survivor must be explained there as equivalent).
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
list=${2:-tests/mutation/mutants.txt}
filter=${3:-}
jobs=${MUTATION_JOBS:-2}
min_killed=${MUTATION_MIN_KILLED:-90}
test_timeout=${MUTATION_TEST_TIMEOUT:-300}
cd "$root"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
case "$list" in /*) ;; *) list="$root/$list" ;; esac
out="$build/mutation"
tree="$out/tree"
save="$out/save"
logs="$out/logs"
report="$out/report.txt"
mkdir -p "$tree" "$save" "$logs"

# ---- the mutant list: blocks of "id: / file: / find: / replace: / tests:" lines ----
ids=(); files=(); finds=(); replaces=(); tests=()
add_block() {
  [ -n "${b_id:-}" ] || return 0
  if [ -z "${b_file:-}" ] || [ -z "${b_find+x}" ] || [ -z "${b_replace+x}" ] || [ -z "${b_tests:-}" ]; then
    echo "mutation: $list: mutant '$b_id' lacks file:, find:, replace: or tests:" >&2; exit 2
  fi
  if [ -z "$filter" ] || [[ "$b_id" =~ $filter ]]; then
    ids+=("$b_id"); files+=("$b_file"); finds+=("$b_find"); replaces+=("$b_replace"); tests+=("$b_tests")
  fi
  unset b_id b_file b_find b_replace b_tests
}
while IFS= read -r line || [ -n "$line" ]; do
  case "$line" in
    '#'*) ;;
    '') add_block ;;
    'id: '*) add_block; b_id=${line#id: } ;;
    'file: '*) b_file=${line#file: } ;;
    'find: '*) b_find=${line#find: } ;;
    'replace: '*) b_replace=${line#replace: } ;;
    'replace:') b_replace= ;;
    'tests: '*) b_tests=${line#tests: } ;;
    *) echo "mutation: $list: cannot read line: $line" >&2; exit 2 ;;
  esac
done < "$list"
add_block
[ "${#ids[@]}" -gt 0 ] || { echo "mutation: no mutant selected" >&2; exit 2; }

# ---- the scratch copy of the source tree ----
git ls-files -co --exclude-standard > "$out/files.txt" || { echo "mutation: needs a git checkout" >&2; exit 2; }
while IFS= read -r f; do
  [ -f "$f" ] || continue
  # New in the copy: keep the file's time (BUILD's objects stay usable); changed: the copy
  # gets the current time, so make rebuilds what was built from the old text.
  if [ ! -e "$tree/$f" ]; then mkdir -p "$tree/$(dirname "$f")" && cp -p "$f" "$tree/$f"
  elif ! cmp -s "$f" "$tree/$f"; then cp "$f" "$tree/$f"; fi
done < "$out/files.txt"
# Files the working tree no longer has (outside the copy's own build folder) go too.
(cd "$tree" && find . -path ./build -prune -o -type f -print | sed 's|^\./||') | sort > "$out/tree_files.txt"
sort "$out/files.txt" | comm -23 "$out/tree_files.txt" - | while IFS= read -r f; do rm -f "$tree/$f"; done

# A first run starts from the objects of BUILD itself (the plain -O2 build `make` made):
# copied with their times, make rebuilds only those older than their sources.
if [ ! -d "$tree/build/obj" ] && [ -d "$build/obj/src" ]; then
  mkdir -p "$tree/build/obj"
  cp -pr "$build/obj/src" "$tree/build/obj/"
  [ -d "$build/obj/tests" ] && cp -pr "$build/obj/tests" "$tree/build/obj/"
  [ -d "$build/pch" ] && cp -pr "$build/pch" "$tree/build/"
fi

all_tests=$(printf '%s\n' "${tests[@]}" | tr ' ' '\n' | sed '/^$/d' | sort -u)
bins() { for t in $1; do printf 'build/tests/%s ' "$t"; done; }
run_make() { (cd "$tree" && make --no-print-directory -j"$jobs" BUILD=build OPT=-O2 "$@"); }

echo "mutation: baseline build in $tree (plain -O2): $(echo $all_tests)"
if ! run_make build/libtiny3d.a $(bins "$all_tests") > "$logs/baseline_build.log" 2>&1; then
  tail -n 20 "$logs/baseline_build.log"; echo "mutation: the baseline does not build" >&2; exit 2
fi
for t in $all_tests; do
  if ! (cd "$tree" && timeout "$test_timeout" "build/tests/$t") > "$logs/baseline_$t.log" 2>&1; then
    tail -n 20 "$logs/baseline_$t.log"; echo "mutation: $t fails without any mutant" >&2; exit 2
  fi
done

# ---- the mutants ----
# find / replace are literal text; "\n" in them stands for a line break (a pattern over
# two lines, where one line alone occurs more than once).
perl_unescape='my $f = $ENV{FIND}; my $r = $ENV{REPLACE} // ""; s/\\n/\n/g for $f, $r;'
killed=0; survived=0; invalid=0; survivors=()
rows=()
row() { rows+=("$(printf '%-34s %-36s %-9s %s' "$1" "$2" "$3" "$4")"); echo "${rows[-1]}"; }
echo "mutation: ${#ids[@]} mutants"
printf '%-34s %-36s %-9s %s\n' "mutant" "file" "result" "by" | tee "$out/header.txt"
for i in "${!ids[@]}"; do
  id=${ids[$i]}; file=${files[$i]}; log="$logs/$id.log"
  target="$tree/$file"
  n=0; [ -f "$target" ] && n=$(FIND=${finds[$i]} perl -0ne "$perl_unescape"'
    my $n = 0; my $at = 0; while (($at = index($_, $f, $at)) >= 0) { ++$n; ++$at; } print $n;' "$target")
  if [ "${n:-0}" -ne 1 ]; then
    row "$id" "$file" "INVALID" "its text occurs $n times"; invalid=$((invalid + 1)); continue
  fi
  # Objects built from this file (their dependency lists name it), saved with their times.
  rm -rf "$save"; mkdir -p "$save"
  cp -p "$target" "$save/source"
  objs=$(grep -lF -- "$file" $(find "$tree/build/obj" -name '*.d') 2>/dev/null | sed 's/\.d$/.o/')
  for o in $objs; do [ -f "$o" ] && mkdir -p "$save/$(dirname "$o")" && cp -p "$o" "$save/$o"; done
  FIND=${finds[$i]} REPLACE=${replaces[$i]} perl -0pi -e "$perl_unescape"'
    my $i = index($_, $f); substr($_, $i, length $f) = $r if $i >= 0;' "$target"
  result=""; by=""
  if cmp -s "$target" "$save/source"; then
    result=INVALID; by="the substitution changes nothing"
  elif ! run_make build/libtiny3d.a $(bins "${tests[$i]}") > "$log" 2>&1; then
    result=INVALID; by="does not compile (see $log)"
  else
    result=SURVIVED; by="${tests[$i]}"
    for t in ${tests[$i]}; do
      (cd "$tree" && timeout "$test_timeout" "build/tests/$t") >> "$log" 2>&1
      rc=$?
      if [ "$rc" -eq 124 ]; then result=KILLED; by="$t (timeout)"; break; fi
      if [ "$rc" -ne 0 ]; then result=KILLED; by=$t; break; fi
    done
  fi
  # Put the file and its objects back; the library is archived again on the next build.
  cp -p "$save/source" "$target"
  for o in $objs; do [ -f "$save/$o" ] && cp -p "$save/$o" "$o"; done
  rm -f "$tree/build/libtiny3d.a"
  case $result in
    KILLED) killed=$((killed + 1)) ;;
    SURVIVED) survived=$((survived + 1)); survivors+=("$id") ;;
    *) invalid=$((invalid + 1)) ;;
  esac
  row "$id" "$file" "$result" "$by"
done

total=${#ids[@]}
valid=$((killed + survived))
percent=0; [ "$valid" -gt 0 ] && percent=$((100 * killed / valid))
unexplained=()
for s in "${survivors[@]}"; do
  grep -qF -- "$s" documentation/reliability.md 2>/dev/null || unexplained+=("$s")
done
closing="mutation: $total mutants, $killed killed, $survived survived, $invalid invalid ($percent % of valid mutants killed)"
{
  echo "libtiny3d mutation check, $(date -u '+%Y-%m-%d %H:%M UTC'), tree of $(git rev-parse --short HEAD 2>/dev/null)$(git diff --quiet 2>/dev/null || echo ' + uncommitted changes')"
  echo "mutants from ${list#$root/}; plain -O2 build; a mutant is killed when one of its tests fails or times out (${test_timeout} s)"
  echo
  cat "$out/header.txt"
  printf '%s\n' "${rows[@]}"
  echo
  [ "${#survivors[@]}" -gt 0 ] && echo "survived: ${survivors[*]}"
  [ "${#unexplained[@]}" -gt 0 ] && echo "survived and not explained in documentation/reliability.md: ${unexplained[*]}"
  echo "$closing"
} > "$report"
[ "${#unexplained[@]}" -gt 0 ] && echo "mutation: survived and not explained in documentation/reliability.md: ${unexplained[*]}"
echo "mutation: report in ${report#$root/}"
echo "$closing"
[ "$invalid" -eq 0 ] && [ "$valid" -gt 0 ] && [ "$percent" -ge "$min_killed" ] && [ "${#unexplained[@]}" -eq 0 ]
