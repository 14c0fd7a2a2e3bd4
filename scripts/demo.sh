#!/usr/bin/env bash
# Quick start, command 1: install what is needed, build (release), install the Python package
# (scripts/install_python.sh: `python3 -c "import pgamesh"` then works from any folder) and run the
# main job on the bundled default mesh.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
cmake --preset release -DPGAMESH_BUILD_TESTS=OFF -DPGAMESH_BUILD_BENCH=OFF > /dev/null
cmake --build --preset release -j "$(nproc)" --target pgamesh_cli pgamesh_python
scripts/install_python.sh build/release
build/release/pgamesh props data/meshes/bunny.stl
