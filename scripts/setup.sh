#!/usr/bin/env bash
# Installs the Debian packages pgamesh needs to build, test and benchmark. Idempotent: it asks apt
# only for what is missing. Usage: scripts/setup.sh [build|test|bench]
set -euo pipefail
what=${1:-build}
pkgs=(cmake g++ make pkg-config libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
      libgmp-dev libcpp-httplib-dev)
case "$what" in
  test) pkgs+=(clang libclang-rt-14-dev clang-format chromium) ;;
  bench) pkgs+=(admesh hyperfine libcgal-dev python3-vtk9 python3-stl python3-open3d python3-numpy time) ;;
esac
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
