#!/usr/bin/env bash
# Quick start, command 1: install what is needed, build (release) and run the main job on the
# bundled default mesh.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
cmake --preset release -DPGAMESH_BUILD_TESTS=OFF -DPGAMESH_BUILD_BENCH=OFF > /dev/null
cmake --build --preset release -j "$(nproc)" --target pgamesh_cli
build/release/pgamesh props data/meshes/bunny.stl
