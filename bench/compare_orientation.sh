#!/bin/sh
# Orientation by nesting (docs/conventions.md §8) against CGAL's
# Polygon_mesh_processing::orient_to_bound_a_volume: the signed volume after
# `pgamesh check --fix-orientation --output` (read back with `pgamesh props`) and after CGAL's
# orientation, on the meshes of bench/orientation_meshes.py.
#   BUILD=build/dev CGAL_ORIENT=build/peers/cgal_orient WORK=/tmp/pgamesh-orientation bench/compare_orientation.sh
# Build the peer with the bench's CMake target `cgal_orient` (needs libcgal-dev), or directly:
#   g++ -std=c++17 -O2 -DNDEBUG bench/peers/cgal_orient.cpp -o build/peers/cgal_orient -lgmp -lmpfr
set -eu
BUILD=${BUILD:-build/dev}
CGAL_ORIENT=${CGAL_ORIENT:-build/peers/cgal_orient}
WORK=${WORK:-/tmp/pgamesh-orientation}
here=$(dirname "$0")
python3 "$here/orientation_meshes.py" "$WORK"
printf '%-26s %22s %22s %22s  %s\n' mesh before pgamesh cgal agree
for f in "$WORK"/*.obj; do
  case $f in *.fixed.obj) continue ;; esac
  name=$(basename "$f" .obj)
  before=$("$BUILD/pgamesh" props "$f" --json | python3 -c 'import json,sys; print(repr(json.load(sys.stdin)["volume"]))')
  "$BUILD/pgamesh" check "$f" --fix-orientation --output "$WORK/$name.fixed.obj" > /dev/null
  ours=$("$BUILD/pgamesh" props "$WORK/$name.fixed.obj" --json | python3 -c 'import json,sys; print(repr(json.load(sys.stdin)["volume"]))')
  theirs=$("$CGAL_ORIENT" "$f" | awk '{print $4}')
  agree=$(python3 -c "import sys; a,b=float('$ours'),float('$theirs'); print('yes' if abs(a-b) <= 1e-12*max(abs(a),abs(b)) else 'NO')")
  printf '%-26s %22s %22s %22s  %s\n' "$name" "$before" "$ours" "$theirs" "$agree"
done
