#!/usr/bin/env bash
# Installs the Python package pgamesh, built in BUILD_DIR/python/pgamesh (CMake option
# PGAMESH_BUILD_PYTHON, target pgamesh_python), for the `python3` on PATH and for Debian's
# /usr/bin/python3, into each one's own site folder (sysconfig's platlib), so that
# `python3 -c "import pgamesh"` works from any folder (docs/python.md, "Installing").
#
# An interpreter that does not see Debian's /usr/lib/python3/dist-packages (a pyenv CPython, say),
# where apt puts numpy and Dask, gets a .pth file appending that folder to its sys.path (after its
# own site-packages, so its own packages still win) when its minor version is Debian's. The module
# is built with the headers of the python3 on PATH; CPython keeps its ABI within a minor version,
# so one build serves every 3.X interpreter; an interpreter of another minor version is skipped.
# Usage: scripts/install_python.sh [BUILD_DIR] (default build/release).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
package="$build/python/pgamesh"
module=$(ls "$package"/_pgamesh.*.so 2> /dev/null | head -n 1 || true)
if [ ! -f "$package/__init__.py" ] || [ -z "$module" ]; then
  echo "install_python: no built package in $package (build the target pgamesh_python)" >&2
  exit 1
fi
module_suffix=${module##*/_pgamesh}
debian_dist=/usr/lib/python3/dist-packages
debian_version=$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2> /dev/null || true)

installed=""
for candidate in "$(command -v python3)" /usr/bin/python3; do
  [ -x "$candidate" ] || continue
  exe=$("$candidate" -c 'import sys; print(sys.executable)')
  case " $installed " in *" $exe "*) continue ;; esac
  suffix=$("$exe" -c 'import sysconfig; print(sysconfig.get_config_var("EXT_SUFFIX"))')
  if [ "$suffix" != "$module_suffix" ]; then
    echo "install_python: $exe expects modules *$suffix, the build made *$module_suffix: skipped" >&2
    continue
  fi
  site=$("$exe" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')
  mkdir -p "$site"
  rm -rf "$site/pgamesh.new"
  cp -r "$package" "$site/pgamesh.new"
  rm -rf "$site/__pycache__/pgamesh"* "$site/pgamesh"
  mv "$site/pgamesh.new" "$site/pgamesh"
  version=$("$exe" -c 'import sys; print("%d.%d" % sys.version_info[:2])')
  sees_debian=$("$exe" -c "import sys; print('$debian_dist' in sys.path)")
  if [ "$sees_debian" = False ] && [ -d "$debian_dist" ] && [ "$version" = "$debian_version" ]; then
    echo "$debian_dist" > "$site/pgamesh-debian-dist-packages.pth"
  fi
  (cd / && "$exe" -c 'import pgamesh, numpy') || {
    echo "install_python: $exe cannot import pgamesh and numpy after the install" >&2
    exit 1
  }
  echo "install_python: pgamesh for $exe in $site"
  installed="$installed $exe"
done
[ -n "$installed" ] || { echo "install_python: no interpreter took the module" >&2; exit 1; }
