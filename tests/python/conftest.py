"""Shared fixtures of the Python tests (docs/python.md, docs/testing.md).

The CLI the figures are checked against is $PGAMESH_CLI (default build/release/pgamesh). The
meshes are data/meshes and, when the folder exists beside the clone, ../shared/meshes.
"""

import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
SHARED_MESHES = REPO.parent / "shared" / "meshes"
MESH_SUFFIXES = {".stl", ".obj", ".ply", ".off", ".3mf", ".gltf", ".glb"}


def mesh_files(folder: pathlib.Path):
    """The mesh files under a folder, sorted."""
    return sorted(p for p in folder.rglob("*") if p.is_file() and p.suffix.lower() in MESH_SUFFIXES)


# The tests name bundled files relative to the repository, as the README does.
os.chdir(REPO)

BUNDLED = mesh_files(REPO / "data" / "meshes")
SHARED = mesh_files(SHARED_MESHES) if SHARED_MESHES.is_dir() else []


@pytest.fixture(scope="session")
def cli() -> str:
    """The pgamesh binary the figures are compared with."""
    path = os.environ.get("PGAMESH_CLI", str(REPO / "build" / "release" / "pgamesh"))
    if not os.access(path, os.X_OK):
        pytest.fail(f"no pgamesh CLI at {path} (set PGAMESH_CLI)")
    return path


def run_cli(cli: str, *args: str):
    """(exit code, parsed JSON or None, stderr) of a CLI run."""
    p = subprocess.run([cli, *args], capture_output=True, text=True, timeout=60)
    return p.returncode, (json.loads(p.stdout) if p.returncode == 0 else None), p.stderr


def shared_or_skip(files):
    """The shared meshes as test parameters, or one skipped parameter saying why."""
    if files:
        return files
    return [pytest.param(None, marks=pytest.mark.skip(
        reason=f"{SHARED_MESHES} is absent: the shared meshes are not checked"))]
