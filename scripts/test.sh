#!/usr/bin/env bash
# Quick start, command 2: install what is needed and run every test — the release build with
# warnings as errors, the same suite under AddressSanitizer + UndefinedBehaviorSanitizer, the
# format check and a bounded libFuzzer run of every reader.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
# Each stage's title, and when it ends its wall time, so a CI log shows where the time goes.
stage_name=""
stage_start=$SECONDS
stage() {
  if [ -n "$stage_name" ]; then echo "== $stage_name: $((SECONDS - stage_start)) s"; fi
  stage_name=$1
  stage_start=$SECONDS
  if [ -n "$stage_name" ]; then echo "== $stage_name"; fi
}

stage "setup"
scripts/setup.sh test

stage "format check"
git ls-files '*.cpp' '*.hpp' | xargs -r clang-format --dry-run --Werror

stage "release build, warnings as errors"
cmake --preset release > /dev/null
cmake --build --preset release -j "$jobs"
stage "release tests"
ctest --preset release -j "$jobs"

if [ -x build/release/pgamesh-serve ]; then
  stage "browser tests (pgamesh serve: API over loopback, the page in headless chromium)"
  PGAMESH_CLI=build/release/pgamesh timeout --kill-after=10 300 node --test tests/viewer/
fi

stage "AddressSanitizer + UndefinedBehaviorSanitizer build"
cmake --preset sanitize > /dev/null
cmake --build --preset sanitize -j "$jobs"
stage "AddressSanitizer + UndefinedBehaviorSanitizer tests"
ctest --preset sanitize -j "$jobs"

if compgen -G "fuzz/fuzz_*.cpp" > /dev/null; then
  stage "libFuzzer harnesses build"
  cmake --preset fuzz > /dev/null
  cmake --build --preset fuzz -j "$jobs"
  stage "libFuzzer, ${PGAMESH_FUZZ_SECONDS:-30} s per reader"
  scripts/fuzz.sh "${PGAMESH_FUZZ_SECONDS:-30}"
fi
stage ""
echo "== all stages: $SECONDS s"
