#!/usr/bin/env bash
# Installs the Debian packages pgamesh needs to build, test and benchmark. Idempotent: it asks apt
# only for what is missing. Usage: scripts/setup.sh [build|test|bench]. The build group includes
# what the Python package needs to build and run (pybind11, the Python headers, numpy, Dask's
# distributed; docs/python.md); scripts/install_python.sh installs the package once built.
set -euo pipefail
what=${1:-build}
pkgs=(cmake ninja-build g++ make pkg-config libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
      libgmp-dev libcpp-httplib-dev libcli11-dev libzip-dev libpugixml-dev pybind11-dev python3-dev
      python3-numpy python3-distributed)
case "$what" in
  test) pkgs+=(clang libclang-rt-14-dev clang-format chromium curl python3-pytest python3-pytest-timeout) ;;
  bench) pkgs+=(admesh hyperfine libcgal-dev python3-vtk9 python3-stl python3-open3d python3-numpy time
                python3-matplotlib assimp-utils valgrind) ;;
esac
# The viewer's page needs node and npm (for three.js and, in tests, playwright-core): Debian's
# only when the machine has none of its own.
command -v npm > /dev/null || pkgs+=(nodejs npm)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The viewer's npm packages (three.js served by `pgamesh serve`; playwright-core drives the browser
# tests), exactly as locked. Skipped when node_modules already matches the lock file.
web=apps/viewer/web
stamp="$web/node_modules/.pgamesh-lock.sha256"
lock_sum=$(sha256sum "$web/package-lock.json" | cut -d' ' -f1)
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$lock_sum" ]; then
  echo "setup: npm ci in $web"
  (cd "$web" && npm ci --no-audit --no-fund --loglevel=error)
  echo "$lock_sum" > "$stamp"
fi
