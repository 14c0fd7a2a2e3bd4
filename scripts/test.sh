#!/usr/bin/env bash
# Quick start, command 2: install what is needed and run every test. The tests are compiled once,
# with clang under AddressSanitizer + UndefinedBehaviorSanitizer (warnings as errors, unity build),
# and run there; the same build makes the libFuzzer harnesses, which replay their corpus and run for
# a bounded time. The release build (GCC, warnings as errors) makes only the programs the
# CLI-level stages use (the installed package, the viewer's server for the browser tests).
# Stage times: docs/testing.md.
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

# The sanitize build needs nothing of the release build, and the stages after the release build
# mostly wait (on the consumer project's configure, on Chromium, on the server's deadlines;
# together about 40 s of CPU in 100 s): it starts now and runs beside them in its own process
# group, at a lower priority so that the release build comes first and the timed tests are not
# stretched (it takes the cores they leave idle), its output kept for the stage that waits for it.
cmake --preset sanitize > /dev/null
sanitize_log=build/sanitize-build.log
mkdir -p build
# Its own process group (job control, for the trap below) but not its own session: the kernel
# shares the CPU between sessions first (autogroups), which would undo the nice.
set -m
nice -n 10 cmake --build --preset sanitize -j "$jobs" > "$sanitize_log" 2>&1 &
sanitize_build=$!
set +m
sanitize_start=$SECONDS
trap 'kill -TERM -- "-$sanitize_build" 2> /dev/null || true' EXIT

stage "release build of the programs (library, pgamesh, pgamesh-serve, Python module), warnings as errors"
cmake --preset release > /dev/null
cmake --build --preset release -j "$jobs" --target pgamesh_cli pgamesh_serve pgamesh_models \
  pgamesh_python

stage "installed package (find_package, the README example, the installed viewer)"
tests/install/run.sh build/release

stage "Python package (installed for python3, pytest against the release pgamesh)"
scripts/install_python.sh build/release
PGAMESH_CLI=build/release/pgamesh timeout --kill-after=10 400 \
  python3 -m pytest -q -p no:cacheprovider tests/python

if [ -x build/release/pgamesh-serve ]; then
  # The installed copy, started from a folder outside the clone: the page, three.js and the
  # bundled meshes must come from the prefix.
  stage "browser tests (installed pgamesh serve: API over loopback, limits, load, the page in headless chromium)"
  rm -rf build/installed
  cmake --install build/release --prefix build/installed > /dev/null
  elsewhere=$(mktemp -d)
  PGAMESH_CLI="$PWD/build/installed/bin/pgamesh" PGAMESH_SERVE_CWD="$elsewhere" \
    timeout --kill-after=10 300 node --test tests/viewer/
  rm -rf "$elsewhere"
fi

stage "AddressSanitizer + UndefinedBehaviorSanitizer build (library, CLI, tests, fuzz harnesses): the rest of it"
sanitize_status=0
wait "$sanitize_build" || sanitize_status=$?
trap - EXIT
cat "$sanitize_log"
echo "(the sanitize build took $((SECONDS - sanitize_start)) s from its start, beside the stages above)"
[ "$sanitize_status" -eq 0 ] || exit "$sanitize_status"
stage "AddressSanitizer + UndefinedBehaviorSanitizer tests"
# One more test program than cores: the CLI tests wait on the processes they start.
ctest --preset sanitize -j "$((jobs + 1))"

stage "libFuzzer: corpus replay, then ${PGAMESH_FUZZ_SECONDS:-6} s per harness, $jobs at a time"
scripts/fuzz.sh "${PGAMESH_FUZZ_SECONDS:-6}"
stage ""
echo "== all stages: $SECONDS s"
