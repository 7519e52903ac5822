#!/usr/bin/env bash
# Image identity check (not part of `make test`; no make): runs every demo of a build (the
# filled ones at --aa 1 and 4), and
# `render` on a mesh at --aa 1/4/8/16 and --threads 1/2, once per kernel table named in
# KERNELS (TINY3D_KERNELS=…, src/kernels.h; a table the CPU does not run falls back to the
# best one, which `render --info` reports), and prints the sha256 of every frame written,
# one "kernels/file hash" line each. Compare the output of two builds with diff: a change
# that must keep the images (a refactor, a faster kernel) prints the same lines.
#   usage: tests/image_identity.sh [BUILD_DIR] [MESH]      (defaults: build, the torus PLY)
#   KERNELS="portable sse2 avx2 avx512" by default; FRAMES=0:3 the frames of each demo.
# A build that predates TINY3D_KERNELS ignores it: every table then prints its best one's
# frames, which is what to compare a newer build's best table with.
set -eu
build=${1:-build}
mesh=${2:-tests/data/torus_binary.ply}
kernels=${KERNELS:-portable sse2 avx2 avx512}
frames=${FRAMES:-0:3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for k in $kernels; do
  export TINY3D_KERNELS=$k
  for d in "$build"/demo/*; do
    name=$(basename "$d")
    dir=$out/$k/$name
    mkdir -p "$dir"
    case $name in
      ply_render) "$d" "$mesh" 0 60 20 "$dir/ply_render.pgm" >/dev/null ;;
      render)
        for aa in 1 4 8 16; do for threads in 1 2; do
          mkdir -p "$dir/aa${aa}_t$threads"
          "$d" "$mesh" --aa "$aa" --threads "$threads" --frames "$frames" --out "$dir/aa${aa}_t$threads" >/dev/null
        done; done ;;
      wireframe) "$d" tests/data/cube_quads.obj --frames "$frames" --out "$dir" >/dev/null ;;
      clock) "$d" --out "$dir" >/dev/null ;;
      lighting|shaded)
        for aa in 1 4; do
          mkdir -p "$dir/aa$aa"
          "$d" --aa "$aa" --frames "$frames" --out "$dir/aa$aa" >/dev/null
        done ;;
      *) "$d" --frames "$frames" --out "$dir" >/dev/null ;;
    esac
  done
done
(cd "$out" && find . -type f | sort | xargs sha256sum | awk '{print substr($2, 3), $1}')
