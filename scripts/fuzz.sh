#!/usr/bin/env bash
# Runs every libFuzzer harness (build/fuzz/fuzz/fuzz_read_*, built by `cmake --preset fuzz &&
# cmake --build --preset fuzz`): first once over every file of its seed corpus (the replay: each
# seed, and each regression input kept there, is a test), then for SECONDS on a scratch copy of it
# fuzz/corpus/<format>/ (the auto-detecting harness gets all of them). The seeds in the repository
# are never modified. Crashes, leaks, timeouts (10 s) and RSS above 2 GB fail the run; the
# reproducer is left in build/fuzz/artifacts/. Usage: scripts/fuzz.sh [SECONDS]  (default 30)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
bin=build/fuzz/fuzz
work=build/fuzz/corpus-work
artifacts=build/fuzz/artifacts
shopt -s nullglob
harnesses=("$bin"/fuzz_read_*)
if [ ${#harnesses[@]} -eq 0 ]; then
  echo "fuzz.sh: no harnesses in $bin; build them with: cmake --preset fuzz && cmake --build --preset fuzz" >&2
  exit 1
fi
mkdir -p "$artifacts"
status=0
for h in "${harnesses[@]}"; do
  name=$(basename "$h")
  format=${name#fuzz_read_}
  rm -rf "${work:?}/$format"
  mkdir -p "$work/$format"
  if [ -d "fuzz/corpus/$format" ]; then
    cp fuzz/corpus/"$format"/* "$work/$format/"
  else
    cp fuzz/corpus/*/* "$work/$format/"
  fi
  if ! "$h" -runs=0 -rss_limit_mb=2048 -timeout=10 "$work/$format" > "$artifacts/$name.replay.log" 2>&1; then
    echo "fuzz.sh: $name FAILED on its corpus; log: $artifacts/$name.replay.log" >&2
    tail -n 40 "$artifacts/$name.replay.log" >&2
    status=1
    continue
  fi
  echo "== $name: corpus of $(ls "$work/$format" | wc -l) replayed, then ${seconds}s"
  if ! "$h" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=16384 \
      -print_final_stats=1 -artifact_prefix="$artifacts/$name-" "$work/$format" \
      > "$artifacts/$name.log" 2>&1; then
    echo "fuzz.sh: $name FAILED; log: $artifacts/$name.log" >&2
    tail -n 40 "$artifacts/$name.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|cov:" "$artifacts/$name.log" | tail -n 2 || true
  fi
done
exit $status
