#!/usr/bin/env bash
# Installs a release build into a temporary prefix and uses it as a user would: builds the README's
# library example (tests/install/consumer) with find_package(pgamesh), checks that it prints the
# volume `pgamesh props` prints, and that the installed server serves its page and three.js from
# another working directory. Usage: tests/install/run.sh BUILD_DIR (a configured, built release
# tree). Prints "N passed, N failed".
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$1" && pwd)
work=$(mktemp -d)
server_pid=""
cleanup() {
  if [ -n "$server_pid" ]; then kill "$server_pid" 2> /dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
passed=0 failed=0
check() {  # check NAME COMMAND...: one test
  if "${@:2}"; then passed=$((passed + 1)); echo "ok: $1"; else failed=$((failed + 1)); echo "FAILED: $1"; fi
}

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"

# The consumer is the README's example, word for word.
readme_example() {
  sed -n '/^## Using the library/,/^## /p' "$repo/README.md" | sed -n '/^```cpp$/,/^```$/p' | sed '1d;$d'
}
check "README example is tests/install/consumer/main.cpp" \
  diff <(readme_example) <(tail -n +2 "$repo/tests/install/consumer/main.cpp")

consumer_builds() {
  cmake -S "$repo/tests/install/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/consumer.log" 2>&1 &&
    cmake --build "$work/consumer" >> "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; return 1; }
}
check "a project builds against the installed package (find_package(pgamesh))" consumer_builds

same_volume() {
  local mesh=$repo/data/meshes/bunny.stl
  local got expected
  got=$(cd "$work" && ./consumer/consumer "$mesh" | sed -n 's/^volume \([^,]*\),.*/\1/p')
  expected=$("$work/prefix/bin/pgamesh" props "$mesh" --json | python3 -c 'import json,sys; print("%.17g" % json.load(sys.stdin)["volume"])')
  [ -n "$got" ] && [ "$got" = "$expected" ] || { echo "consumer: '$got', pgamesh props: '$expected'"; return 1; }
}
check "the consumer prints the volume pgamesh props prints" same_volume

serves_page() {
  mkdir -p "$work/elsewhere"
  (cd "$work/elsewhere" && exec "$work/prefix/bin/pgamesh" serve --port 0 --quiet > "$work/serve.out" 2> "$work/serve.err") &
  server_pid=$!
  local url=""
  for _ in $(seq 100); do
    url=$(sed -n 's/^pgamesh serve: listening on \(http:[^ ]*\)$/\1/p' "$work/serve.out")
    [ -n "$url" ] && break
    sleep 0.1
  done
  [ -n "$url" ] || { cat "$work/serve.err"; return 1; }
  if grep -q "missing" "$work/serve.err"; then cat "$work/serve.err"; return 1; fi
  # Saved, then searched: `curl | grep -q` fails under pipefail when grep stops reading first.
  curl -sf "$url" -o "$work/page.html" && grep -q "<html" "$work/page.html" &&
    curl -sf "${url}vendor/three/three.module.js" -o /dev/null &&
    curl -sf "${url}api/meshes" -o "$work/meshes.json" && grep -q "bunny" "$work/meshes.json"
}
check "the installed server serves its page, three.js and bundled meshes from another folder" serves_page

echo "install: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
