#!/usr/bin/env bash
# Whole-process timings of `pgamesh props` against the I/O floor (cat FILE > /dev/null) and peer
# tools from Debian, on generated closed tori of 10^3 ... 10^7 triangles, in one run. Reports wall
# time (best of REPEAT rounds in which the tools take turns, warm page cache), peak resident memory
# (/usr/bin/time %M, worst run) and ratios as a Markdown table.
#
#   bench/compare_peers.sh [TRIANGLES ...]          default: 1000 10000 100000 1000000
#   FORMATS="stl stl-ascii obj ply ply-bin" REPEAT=3 WORK=/tmp/pgamesh-bench BUILD=build/release CGAL=0|1
#   PEERS="admesh numpy-stl cgal vtk open3d"   (the peers to run; e.g. PEERS=admesh for 10^7, where
#                                               the Python peers take minutes per run)
#   BASELINE=/path/to/older/pgamesh   (another build of pgamesh, timed beside this one in the same
#                                      rounds: the rows "baseline …"; compare them with the rows of
#                                      this build — "vs pgamesh" is relative to this build's props)
#   PROPS_ARGS="--no-self-intersections"   (options of this build's `pgamesh props` with topology,
#                                      e.g. to leave out the search for intersecting faces, which
#                                      an older build or a peer does not make)
#
# Peers (scripts/setup.sh bench installs them; missing ones are skipped): admesh (STL), a CGAL
# program (bench/peers/cgal_props.cpp: PMP::volume/area/centroid), VTK vtkMassProperties
# (python3-vtk9), Open3D load + area (python3-open3d), numpy-stl (python3-stl, STL only).
# Columns: "x floor" = wall / cat's wall; "vs pgamesh" = wall / wall of `pgamesh props` (with
# topology, the like-for-like pass) on the same file; RSS / file = peak resident memory / file size.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${BUILD:-build/release}
work=${WORK:-/tmp/pgamesh-bench}
repeat=${REPEAT:-3}
formats=${FORMATS:-"stl stl-ascii obj ply ply-bin"}
sizes=("$@")
[ ${#sizes[@]} -eq 0 ] && sizes=(1000 10000 100000 1000000)
mkdir -p "$work"

if [ ! -x "$build/pgamesh" ] || [ ! -x "$build/bench/pgamesh_gen_mesh" ]; then
  cmake --preset release > /dev/null
  cmake --build --preset release -j2 --target pgamesh_cli pgamesh_gen_mesh > /dev/null
fi
pgamesh=$root/$build/pgamesh
gen=$root/$build/bench/pgamesh_gen_mesh
cgal=$root/$build/bench/cgal_props
peers=${PEERS:-"admesh numpy-stl cgal vtk open3d"}
wanted() { [[ " $peers " == *" $1 "* ]]; }
if [ "${CGAL:-1}" = 0 ] || ! wanted cgal; then
  cgal=/nonexistent  # leave the CGAL peer out (building it takes minutes)
elif [ ! -x "$cgal" ] && dpkg-query -W -f='${Status}' libcgal-dev 2>/dev/null | grep -q "ok installed"; then
  echo "building the CGAL peer (takes a minute or two)..." >&2
  cmake --build --preset release -j2 --target cgal_props > /dev/null 2>&1 || true
fi
have() { command -v "$1" > /dev/null 2>&1; }
pymod() { /usr/bin/python3 -c "import $1" > /dev/null 2>&1; }
have_admesh=$(wanted admesh && have admesh && echo 1 || echo 0)
have_vtk=$(wanted vtk && pymod vtk && echo 1 || echo 0)
have_o3d=$(wanted open3d && pymod open3d && echo 1 || echo 0)
have_nstl=$(wanted numpy-stl && pymod stl && echo 1 || echo 0)
have_cgal=$(wanted cgal && [ -x "$cgal" ] && echo 1 || echo 0)

# run_once CMD...: wall nanoseconds and peak RSS (kB) of one run -> "$wall $rss", or "fail" when
# the tool exits non-zero or runs for more than 15 minutes. Standard output goes to /dev/null, so
# that cat measures the read floor: written to a file, its copy of the mesh would time the page
# cache's writes too (2-5 x the read at 10^6-10^7 triangles), and their writeback would slow the
# tool run after it.
run_once() {
  local t0 t1
  t0=$(date +%s%N)
  if ! /usr/bin/time -f %M -o "$work/rss" timeout 900 "$@" > /dev/null 2> "$work/err"; then
    echo fail
    return
  fi
  t1=$(date +%s%N)
  echo "$(( t1 - t0 )) $(tail -1 "$work/rss")"
}

ext_of() {
  case $1 in
    stl) echo bin.stl ;; stl-ascii) echo ascii.stl ;; ply-bin) echo bin.ply ;; *) echo "$1" ;;
  esac
}

echo "| triangles | format | file MB | tool | wall s | x floor | vs pgamesh | peak RSS MB | RSS / file |"
echo "|---:|---|---:|---|---:|---:|---:|---:|---:|"
for n in "${sizes[@]}"; do
  for fmt in $formats; do
    file=$work/torus_$n.$(ext_of "$fmt")
    [ -s "$file" ] || "$gen" "$n" "$fmt" "$file" > /dev/null
    bytes=$(stat -c %s "$file")
    cat "$file" > /dev/null  # warm the page cache
    tools=("cat" "pgamesh props --no-topology" "pgamesh props")
    cmds=("cat $file" "$pgamesh props $file --no-topology --json"
          "$pgamesh props $file --json ${PROPS_ARGS:-}")
    if [ -n "${BASELINE:-}" ]; then
      tools+=("baseline props --no-topology" "baseline props")
      cmds+=("$BASELINE props $file --no-topology --json" "$BASELINE props $file --json")
    fi
    case $fmt in stl|stl-ascii)
      [ "$have_admesh" = 1 ] && { tools+=("admesh"); cmds+=("admesh $file"); }
      [ "$have_nstl" = 1 ] && { tools+=("numpy-stl"); cmds+=("/usr/bin/python3 $root/bench/peers/numpy_stl_props.py $file"); } ;;
    esac
    [ "$have_cgal" = 1 ] && { tools+=("CGAL PMP"); cmds+=("$cgal $file"); }
    if [ "$fmt" != off ]; then
      [ "$have_vtk" = 1 ] && { tools+=("VTK"); cmds+=("/usr/bin/python3 $root/bench/peers/vtk_props.py $file"); }
      [ "$have_o3d" = 1 ] && { tools+=("Open3D"); cmds+=("/usr/bin/python3 $root/bench/peers/open3d_props.py $file"); }
    fi
    # REPEAT rounds, each running every tool once in turn, so that a drift in the machine's speed
    # (other work, the VM's memory) reaches all tools alike; best wall and worst RSS per tool.
    best=() rss=() failed=()
    for _ in $(seq "$repeat"); do
      for i in "${!tools[@]}"; do
        [ "${failed[$i]:-0}" = 1 ] && continue
        # shellcheck disable=SC2086
        r=$(run_once ${cmds[$i]})
        if [ "$r" = fail ]; then
          failed[i]=1
          continue
        fi
        read -r ns kb <<< "$r"
        if [ -z "${best[$i]:-}" ] || [ "$ns" -lt "${best[$i]}" ]; then best[i]=$ns; fi
        if [ "$kb" -gt "${rss[$i]:-0}" ]; then rss[i]=$kb; fi
      done
    done
    floor="" ref=""
    for i in "${!tools[@]}"; do
      if [ "${failed[$i]:-0}" = 1 ]; then
        echo "| $n | $fmt | $(awk "BEGIN{printf \"%.1f\", $bytes/1e6}") | ${tools[$i]} | fail | | | | |"
        continue
      fi
      ns=${best[$i]} kb=${rss[$i]}
      [ -z "$floor" ] && floor=$ns
      [ "${tools[$i]}" = "pgamesh props" ] && ref=$ns
      awk -v n="$n" -v f="$fmt" -v b="$bytes" -v t="${tools[$i]}" -v ns="$ns" -v kb="$kb" \
          -v fl="$floor" -v ref="$ref" 'BEGIN {
        vs = (ref == "" ? "" : sprintf("%.2f", ns / ref));
        printf "| %d | %s | %.1f | %s | %.3f | %.1f | %s | %.1f | %.2f |\n",
               n, f, b / 1e6, t, ns / 1e9, ns / fl, vs, kb / 1024, kb * 1024 / b }'
    done
  done
done
