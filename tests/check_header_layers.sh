#!/usr/bin/env bash
# Checks that the modules depend on each other one way (run by `make test-portable`). The
# modules, lowest first; a module may include only modules before it:
LAYERS="tiny3d_result math3d animation canvas lines lighting material mesh pipeline parallel raster wireframe lab scene"
# Checked: every include/<module>.h and every file under src/<module>/, at any depth (its
# "<module>.h" includes and its path includes, "../<folder>/…" or "../../<folder>/…": the
# src/<folder>/ they reach). The compat layer's two documented exceptions
# are not module headers: include/compat/canvas_alias.h pulls in lines.h (the report's
# canvas.h declared draw_line_f), and renderer.h / tiny3d.h gather modules for programs.
# Prints what it found and "header layers: N passed, N failed"; exits non-zero on a failure.
set -u
cd "$(dirname "$0")/.."
passed=0; failed=0
rank() { local i=0 m; for m in $LAYERS; do [ "$m" = "$1" ] && { echo $i; return; }; i=$((i + 1)); done; echo -1; }

# check FILE MODULE: FILE belongs to MODULE (a module header may not include itself)
check() {
  local f=$1 own=$2 r_own inc r m bad=0
  r_own=$(rank "$own")
  for inc in $(grep -oE '^[[:space:]]*#[[:space:]]*include "[^"]+"' "$f" | sed -E 's/.*"([^"]+)"/\1/'); do
    case $inc in
      */*)                                         # a path: the src/<module>/ folder it names
        m=$(realpath -m --relative-to=. "$(dirname "$f")/$inc")
        case $m in src/*/*) m=${m#src/}; m=${m%%/*} ;; *) continue ;; esac ;;
      *.h) m=${inc%.h} ;;
      *) continue ;;
    esac
    r=$(rank "$m")
    [ "$r" -lt 0 ] && continue                     # not a module (internal header, simd_config.h)
    if [ "$r" -gt "$r_own" ] || { [ "$r" -eq "$r_own" ] && [ "$f" = "include/$own.h" ]; }; then
      echo "  $f ($own) includes $inc ($m): a module includes only modules below it"
      bad=1
    fi
  done
  if [ $bad -eq 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
}

for m in $LAYERS; do
  [ -f "include/$m.h" ] && check "include/$m.h" "$m"
  [ -d "src/$m" ] && for f in $(find "src/$m" -name '*.cpp' -o -name '*.h' | sort); do check "$f" "$m"; done
done
# Every public header is a module header, the report's gathering header or tiny3d.h.
for h in include/*.h; do
  b=$(basename "$h" .h)
  if [ "$(rank "$b")" -lt 0 ] && [ "$b" != renderer ] && [ "$b" != tiny3d ] && [ "$b" != tiny3d_compat ]; then
    echo "  $h: not a module header (add it to LAYERS in tests/check_header_layers.sh)"
    failed=$((failed + 1))
  fi
done
echo "header layers: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
