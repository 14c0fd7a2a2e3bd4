#!/bin/bash
# Self-intersections (docs/topology.md, "Self-intersections") against CGAL's
# Polygon_mesh_processing::self_intersections: the intersecting face pairs `pgamesh check --json`
# reports and those CGAL reports (the counts, and whether the lists of pairs are the same), on the
# meshes of bench/self_intersection_meshes.py and the STL and OFF meshes of data/meshes and
# ../shared/meshes (when present), then both timed on a 10^6-triangle torus of bench/gen_mesh.cpp
# (pgamesh: the whole `check` with and without the pass; CGAL: its call alone).
#   BUILD=build/dev CGAL_SI=build/peers/cgal_self_intersections bench/compare_self_intersections.sh
# Build the peer with the bench's CMake target `cgal_self_intersections` (needs libcgal-dev), or:
#   nice -n 10 g++ -std=c++17 -O2 -DNDEBUG bench/peers/cgal_self_intersections.cpp \
#     -o build/peers/cgal_self_intersections -lgmp -lmpfr
set -eu
BUILD=${BUILD:-build/dev}
CGAL_SI=${CGAL_SI:-build/peers/cgal_self_intersections}
GEN=${GEN:-$BUILD/bench/pgamesh_gen_mesh}  # or build/peers/pgamesh_gen_mesh (g++ -O2 bench/gen_mesh.cpp)
WORK=${WORK:-/tmp/pgamesh-self-intersections}
here=$(dirname "$0")
root=$here/..
python3 "$here/self_intersection_meshes.py" "$WORK"

ours() {  # the count, then every pair, from pgamesh check
  "$BUILD/pgamesh" check "$1" --json --max-list 100000000 | python3 -c '
import json, sys
j = json.load(sys.stdin)
print(j["self_intersecting_pairs"])
for p in j["self_intersection_list"]: print(p["face0"], p["face1"])'
}

printf '%-40s %8s %8s %6s %6s  %s\n' mesh pgamesh cgal agree pairs note
for f in "$WORK"/*.off "$root"/data/meshes/*.stl "$root"/../shared/meshes/*/*.stl \
         "$root"/../shared/meshes/*/*.off; do
  [ -f "$f" ] || continue
  "$CGAL_SI" "$f" --pairs > "$WORK/cgal.txt" 2>/dev/null ||
    { printf '%-40s (CGAL cannot read it)\n' "$(basename "$f")"; continue; }
  theirs_line=$(head -1 "$WORK/cgal.txt")
  theirs=$(echo "$theirs_line" | awk '{print $2}')
  degenerate=$(echo "$theirs_line" | awk '{print $4}')
  note=$(echo "$theirs_line" | sed -n 's/.*(\(.*\))/\1/p')
  [ "$degenerate" != 0 ] && note="$degenerate degenerate faces (CGAL: pairs (f, f)) $note"
  ours "$f" > "$WORK/ours.txt"
  mine=$(head -1 "$WORK/ours.txt")
  agree=$([ "$mine" = "$theirs" ] && echo yes || echo NO)
  same=$(cmp -s <(tail -n +2 "$WORK/ours.txt") <(tail -n +2 "$WORK/cgal.txt") && echo same || echo differ)
  printf '%-40s %8s %8s %6s %6s  %s\n' "$(basename "$f")" "$mine" "$theirs" "$agree" "$same" "$note"
done

# Timing: 10^6 triangles.
big=$WORK/torus_1e6.off
[ -f "$big" ] || "$GEN" 1000000 off "$big"
echo
echo "10^6-triangle torus ($(uptime | sed 's/.*load average: //') load):"
for run in 1 2 3; do
  with=$( { /usr/bin/time -f '%e %U' "$BUILD/pgamesh" check "$big" --json --max-list 0 > /dev/null; } 2>&1)
  without=$( { /usr/bin/time -f '%e %U' "$BUILD/pgamesh" check "$big" --json --max-list 0 --no-self-intersections > /dev/null; } 2>&1)
  cgal=$("$CGAL_SI" "$big")
  echo "  pgamesh check: $with s (wall, user) with the pass, $without s without; cgal: $cgal"
done
