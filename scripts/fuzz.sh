#!/usr/bin/env bash
# Runs every libFuzzer harness (build/sanitize/fuzz/fuzz_*, built with the tests by `cmake
# --preset sanitize && cmake --build --preset sanitize`): first once over every file of its seed
# corpus (the replay: each seed, and each regression input kept there, is a test), then for SECONDS
# on a scratch copy of it: fuzz/corpus/<name>/ for fuzz_read_<name> and fuzz_<name> (the
# auto-detecting reader gets all the readers' seeds, fuzz_read_ply_topology the PLY ones,
# fuzz_gltf_stream the glTF ones). As many harnesses run at once as there are cores. The seeds in
# the repository are never modified.
# Crashes, leaks, timeouts (10 s) and RSS above 2 GB fail the run; the reproducer is left in
# build/sanitize/fuzz-artifacts/. Usage: scripts/fuzz.sh [SECONDS]  (default 30)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
bin=build/sanitize/fuzz
work=build/sanitize/fuzz-corpus-work
artifacts=build/sanitize/fuzz-artifacts
shopt -s nullglob
harnesses=("$bin"/fuzz_*)
if [ ${#harnesses[@]} -eq 0 ]; then
  echo "fuzz.sh: no harnesses in $bin; build them with: cmake --preset sanitize && cmake --build --preset sanitize" >&2
  exit 1
fi
mkdir -p "$artifacts"

# One harness: replay its corpus, then fuzz for $seconds. Prints its report when it ends.
fuzz_one() {
  local h=$1 name format
  name=$(basename "$h")
  format=${name#fuzz_}
  format=${format#read_}
  rm -rf "${work:?}/$format"
  mkdir -p "$work/$format"
  if [ -d "fuzz/corpus/$format" ]; then
    cp fuzz/corpus/"$format"/* "$work/$format/"
  elif [ -d "fuzz/corpus/${format%%_*}" ]; then  # fuzz_read_ply_topology: the PLY seeds
    cp fuzz/corpus/"${format%%_*}"/* "$work/$format/"
  elif [ "$format" = auto ]; then
    cp fuzz/corpus/{obj,off,ply,stl}/* "$work/$format/"
  fi
  if ! "$h" -runs=0 -rss_limit_mb=2048 -timeout=10 "$work/$format" > "$artifacts/$name.replay.log" 2>&1; then
    echo "fuzz.sh: $name FAILED on its corpus; log: $artifacts/$name.replay.log" >&2
    tail -n 40 "$artifacts/$name.replay.log" >&2
    return 1
  fi
  if ! "$h" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=16384 \
      -print_final_stats=1 -artifact_prefix="$artifacts/$name-" "$work/$format" \
      > "$artifacts/$name.log" 2>&1; then
    echo "fuzz.sh: $name FAILED; log: $artifacts/$name.log" >&2
    tail -n 40 "$artifacts/$name.log" >&2
    return 1
  fi
  echo "== $name: corpus of $(ls "$work/$format" | wc -l) replayed, then ${seconds}s;" \
    "$(grep -E "stat::number_of_executed_units" "$artifacts/$name.log" | tr -s ' ')"
}

status=0
running=0
for h in "${harnesses[@]}"; do
  fuzz_one "$h" &
  running=$((running + 1))
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
