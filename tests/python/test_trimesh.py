"""The trimesh vocabulary against trimesh itself, when a trimesh source folder is given.

trimesh is never a dependency: set PGAMESH_TRIMESH to a folder holding its package (e.g. one
extracted with `git archive 4.9.0 trimesh`, docs/python.md "Speed") to run these; they are
skipped, saying so, otherwise.
"""

import os
import sys

import numpy as np
import pytest

import pgamesh

FOLDER = os.environ.get("PGAMESH_TRIMESH")
pytestmark = pytest.mark.skipif(not FOLDER, reason="PGAMESH_TRIMESH is not set: no trimesh to "
                                                    "compare with")


@pytest.fixture(scope="module")
def trimesh():
    sys.path.insert(0, FOLDER)
    try:
        import trimesh as module
    finally:
        sys.path.remove(FOLDER)
    return module


@pytest.mark.parametrize("path", ["data/meshes/bunny.stl", "data/meshes/tank.obj"])
def test_same_figures_as_trimesh(trimesh, path):
    theirs, ours = trimesh.load(path), pgamesh.load(path)
    scale = np.max(np.abs(ours.moment_inertia))
    assert ours.volume == pytest.approx(theirs.volume, rel=1e-12)
    assert ours.area == pytest.approx(theirs.area, rel=1e-12)
    np.testing.assert_allclose(ours.center_mass, theirs.center_mass, rtol=0,
                               atol=1e-12 * np.max(np.ptp(ours.vertices, axis=0)))
    # The same tensor, sign convention included (I_xy = -∫xy dm).
    np.testing.assert_allclose(ours.moment_inertia, theirs.moment_inertia, rtol=0,
                               atol=1e-12 * scale)
    np.testing.assert_allclose(ours.principal_inertia_components,
                               np.sort(theirs.principal_inertia_components), rtol=1e-10)
    assert ours.is_watertight == theirs.is_watertight
    assert ours.is_winding_consistent == theirs.is_winding_consistent
