#!/usr/bin/env bash
# Quick start, command 2: install what is needed and run every test — the release build with
# warnings as errors, the same suite under AddressSanitizer + UndefinedBehaviorSanitizer, the
# format check and a bounded libFuzzer run of every reader.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
scripts/setup.sh test

echo "== format check"
git ls-files '*.cpp' '*.hpp' | xargs -r clang-format --dry-run --Werror

echo "== release build, warnings as errors"
cmake --preset release > /dev/null
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs"

if [ -x build/release/pgamesh-serve ]; then
  echo "== browser tests (pgamesh serve: API over loopback, the page in headless chromium)"
  PGAMESH_CLI=build/release/pgamesh timeout --kill-after=10 300 node --test tests/viewer/
fi

echo "== AddressSanitizer + UndefinedBehaviorSanitizer"
cmake --preset sanitize > /dev/null
cmake --build --preset sanitize -j "$jobs"
ctest --preset sanitize -j "$jobs"

if compgen -G "fuzz/fuzz_*.cpp" > /dev/null; then
  echo "== libFuzzer, ${PGAMESH_FUZZ_SECONDS:-30} s per reader"
  cmake --preset fuzz > /dev/null
  cmake --build --preset fuzz -j "$jobs"
  scripts/fuzz.sh "${PGAMESH_FUZZ_SECONDS:-30}"
fi
