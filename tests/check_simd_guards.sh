#!/usr/bin/env bash
# Checks that src/simd_config.h is the one SIMD switch (run by `make test-portable`):
# no source, header or test tests the compiler's instruction-set macros (__SSE2__,
# __AVX512F__ …) itself, and every file that tests TINY3D_SSE2 / TINY3D_AVX2 / TINY3D_AVX512 includes
# simd_config.h (a file that forgot it would silently compile its portable path only).
# Prints what it found and "simd guards: N passed, N failed"; exits non-zero on a failure.
set -u
cd "$(dirname "$0")/.."
failed=0; passed=0
files=$(find src include tests demo -name '*.cpp' -o -name '*.h' -o -name '*.c' | grep -v '^src/simd_config.h$' | sort)
for f in $files; do
  if grep -nE '^[[:space:]]*#[[:space:]]*(if|ifdef|ifndef|elif).*__(SSE|AVX|MMX|FMA)[0-9A-Z_]*__' "$f"; then
    echo "  $f: tests an instruction-set macro itself (use TINY3D_SSE2 / TINY3D_AVX2 / TINY3D_AVX512 from src/simd_config.h)"
    failed=$((failed + 1)); continue
  fi
  if grep -qE 'TINY3D_(SSE2|AVX2|AVX512)' "$f"; then
    if grep -qE '#include "([./]*|\.\./src/|\.\./\.\./src/)simd_config\.h"' "$f"; then passed=$((passed + 1))
    else echo "  $f: tests TINY3D_SSE2/TINY3D_AVX2/TINY3D_AVX512 without including simd_config.h"; failed=$((failed + 1)); fi
  fi
done
echo "simd guards: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
