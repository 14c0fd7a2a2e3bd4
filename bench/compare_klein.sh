#!/usr/bin/env bash
# The PGA3 kernels of pgamesh (double and float) beside klein (jeremyong/klein, float SSE) in one
# Google Benchmark binary (bench/bench_pga3.cpp built as bench_pga3_klein): same compiler, same
# flags, same input rings. Prints the check that both give the same answers on every input, then
# the medians of REPS repetitions as a Markdown table (docs/pga3.md "Speed").
#
#   bench/compare_klein.sh KLEIN
#     KLEIN: a klein git repository (bare or not; its HEAD is used) or a folder holding
#            public/klein/klein.hpp. klein is extracted into $BUILD/peers/klein, never into the
#            sources.
#   BUILD=build/bench-klein  REPS=10  CPU=1 (taskset core; empty: no pinning)
#   CXXFLAGS_EXTRA="-march=native"  (extra compiler flags for both libraries; default: none)
#   COUNT=1  also count instructions per item under valgrind's callgrind (noise-free on a loaded
#            machine): Ir inside each benchmark function per item, loop and DoNotOptimize included
#            (the same loop for both libraries), over a fixed number of iterations
#            (PGAMESH_BENCH_ITERATIONS). COUNT=0 skips it.
set -euo pipefail
cd "$(dirname "$0")/.."
klein=${1:?usage: bench/compare_klein.sh KLEIN (git dir or folder with public/klein)}
build=${BUILD:-build/bench-klein}
reps=${REPS:-10}
cpu=${CPU-1}

rm -rf "$build/peers/klein"
mkdir -p "$build/peers/klein"
if [ -f "$klein/public/klein/klein.hpp" ]; then
  cp -r "$klein/public" "$build/peers/klein/"
elif git --git-dir="$klein" rev-parse --verify -q HEAD > /dev/null 2>&1; then
  git --git-dir="$klein" archive HEAD public | tar -x -C "$build/peers/klein"
elif git --git-dir="$klein/.git" rev-parse --verify -q HEAD > /dev/null 2>&1; then
  git --git-dir="$klein/.git" archive HEAD public | tar -x -C "$build/peers/klein"
else
  echo "compare_klein.sh: no klein sources at $klein" >&2
  exit 1
fi

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPGAMESH_BUILD_TESTS=OFF \
  -DPGAMESH_BUILD_VIEWER=OFF "-DCMAKE_CXX_FLAGS=${CXXFLAGS_EXTRA:-}" \
  "-DPGAMESH_KLEIN_DIR=$(pwd)/$build/peers/klein/public" > "$build/configure.log"
nice -n 10 ninja -C "$build" -j1 bench_pga3_klein > "$build/build.log"

run=("$build/bench/bench_pga3_klein")
[ -n "$cpu" ] && command -v taskset > /dev/null && run=(taskset -c "$cpu" "${run[@]}")
nice -n -5 true 2> /dev/null && run=(nice -n -5 "${run[@]}")
# Repetitions of all the benchmarks interleaved in random order: run one after the other, a
# library's benchmarks met other phases of a shared machine than the other's (on the VM of
# docs/pga3.md the ratios of two runs in a row differed by up to 0.4).
"${run[@]}" --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
  --benchmark_enable_random_interleaving=true \
  --benchmark_format=json --benchmark_out="$build/bench_pga3_klein.json" \
  --benchmark_out_format=json | grep '^klein agrees'

names=(MotorTimesMotor SandwichPoint SandwichPlane SandwichLine JoinThreePoints Exp Log
  SandwichPointArray SandwichPlaneArray)
counts="$build/instructions.txt"
: > "$counts"
if [ "${COUNT:-1}" = 1 ] && command -v valgrind > /dev/null; then
  for name in "${names[@]}"; do
    for bm in "BM_$name<double>" "BM_$name<float>" "BM_Klein_$name"; do
      iterations=100000 per_iteration=1  # the batch benchmarks: 1024 items per iteration
      [[ $name == *Array ]] && iterations=1000 per_iteration=1024
      PGAMESH_BENCH_ITERATIONS=$iterations valgrind --tool=callgrind \
        --callgrind-out-file="$build/callgrind.out" --collect-atstart=no \
        "--toggle-collect=*$bm(*" "$build/bench/bench_pga3_klein" "--benchmark_filter=^$bm(/|$)" \
        > /dev/null 2>&1
      echo "$bm $(sed -n 's/^totals: //p' "$build/callgrind.out") $((iterations * per_iteration))" \
        >> "$counts"
    done
  done
fi

python3 - "$build/bench_pga3_klein.json" "$counts" << 'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
# ns per item: the batch benchmarks process 1024 items per iteration.
per_item = {b["run_name"]: 1e9 / b["items_per_second"] for b in doc["benchmarks"]
            if b.get("aggregate_name") == "median"}
instr = {}
for line in open(sys.argv[2]):
    name, ir, items = line.split()
    instr[name] = int(ir) / int(items)
rows = [("motor × motor", "MotorTimesMotor"), ("motor sandwich of a point", "SandwichPoint"),
        ("motor sandwich of a plane", "SandwichPlane"), ("motor sandwich of a line", "SandwichLine"),
        ("join of three points", "JoinThreePoints"), ("exp of a bivector", "Exp"),
        ("log of a motor", "Log"), ("1024 points, per point", "SandwichPointArray"),
        ("1024 planes, per plane", "SandwichPlaneArray")]
ctx = doc["context"]
print(f"{ctx.get('num_cpus')} CPUs at {ctx.get('mhz_per_cpu')} MHz, load "
      f"{', '.join(f'{x:.1f}' for x in ctx.get('load_avg', []))}; medians of the repetitions, "
      "CPU ns per item" + ("; instructions per item (callgrind) in brackets" if instr else ""))
print()
print("| operation | pgamesh double | pgamesh float | klein (float SSE) | double / klein | float / klein |")
print("|---|---:|---:|---:|---:|---:|")
def cell(bm):
    t = per_item.get(bm)
    if t is None:
        return "—"
    return f"{t:.2f}" + (f" [{instr[bm]:.0f}]" if bm in instr else "")
ratio = lambda a, b: "—" if a is None or b is None else f"{a / b:.2f}"
for label, name in rows:
    d, f, k = f"BM_{name}<double>", f"BM_{name}<float>", f"BM_Klein_{name}"
    print(f"| {label} | {cell(d)} | {cell(f)} | {cell(k)} | "
          f"{ratio(per_item.get(d), per_item.get(k))} | {ratio(per_item.get(f), per_item.get(k))} |")
PY
