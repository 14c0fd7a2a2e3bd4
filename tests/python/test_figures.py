"""Every figure of the Python API against `pgamesh props --json` / `check --json` on real meshes."""

import math

import numpy as np
import pytest

import pgamesh
from conftest import BUNDLED, SHARED, run_cli, shared_or_skip


def same(value, reference):
    """Bitwise equality of a figure with the CLI's JSON value (null = NaN, or absent)."""
    if reference is None:
        return value is None or bool(np.all(np.isnan(np.asarray(value, dtype=float))))
    return np.array_equal(np.asarray(value, dtype=float), np.asarray(reference, dtype=float))


def check_file(cli, path):
    code, doc, err = run_cli(cli, "props", str(path), "--json")
    if code != 0:
        # A file the CLI refuses is refused by the binding too, as an InputError (a ValueError).
        with pytest.raises(ValueError):
            pgamesh.analyze_file(str(path))
        with pytest.raises(ValueError):
            pgamesh.load(str(path))
        return
    # analyze_file is the CLI's document, bit for bit (a str or a pathlib.Path).
    assert pgamesh.analyze_file(str(path)) == doc
    assert pgamesh.analyze_file(path) == doc
    mesh = pgamesh.load(str(path))
    assert mesh.props() == doc
    assert mesh.format == doc["format"]
    assert mesh.triangles == doc["triangles"]
    assert mesh.area == doc["area"]
    assert mesh.volume == doc["volume"]
    assert same(mesh.center_mass, doc["center_of_mass"])
    assert same(mesh.moment_inertia, doc["inertia_com"])
    assert same(mesh.principal_inertia_components, doc["principal_moments"])
    assert same(mesh.principal_inertia_vectors, doc["principal_axes"])
    assert mesh.gap_area == doc["gap_area"]
    assert mesh.is_winding_consistent == doc["orientation_consistent"]
    assert mesh.is_watertight == (doc["boundary_edges"] == 0 and doc["nonmanifold_edges"] == 0)
    mp = mesh.mass_properties(density=2.5)
    # With topology: the reading the mesh's figures come from (the streamed sums of --fast place
    # their reference point by a sample, and may differ in the last bits).
    code, doc25, _ = run_cli(cli, "props", str(path), "--json", "--density", "2.5",
                             "--no-self-intersections")
    if code == 0:
        assert mp["mass"] == doc25["mass"]
        assert same(mp["inertia"], doc25["inertia_com"])
        assert same(mp["center_mass"], doc25["center_of_mass"])
    # The topology report is `pgamesh check --json`'s fields.
    code, check, _ = run_cli(cli, "check", str(path), "--json")
    assert code == 0
    report = mesh.check()
    for field, value in report.items():
        assert check[field] == value, field
    loops = mesh.boundary_loops
    assert len(loops) == check["boundary_loop_count"]
    assert sum(loop["area"] for loop in loops) == pytest.approx(check["boundary_loops_area"],
                                                                rel=1e-12, abs=1e-300)


@pytest.mark.parametrize("path", BUNDLED, ids=lambda p: p.name)
def test_bundled_mesh_matches_cli(cli, path):
    check_file(cli, path)


@pytest.mark.parametrize("path", shared_or_skip(SHARED),
                         ids=lambda p: "skipped" if p is None else f"{p.parent.name}/{p.name}")
def test_shared_mesh_matches_cli(cli, path):
    check_file(cli, path)


def test_bunny_volume_is_the_cli_volume(cli):
    code, doc, _ = run_cli(cli, "props", "data/meshes/bunny.stl", "--json")
    assert code == 0
    assert pgamesh.load("data/meshes/bunny.stl").volume == doc["volume"]


def test_trimesh_inertia_convention():
    # A box [0,2]×[0,1]×[0,1] shifted off the axes: about its centre the tensor is diagonal
    # (m/12)(b²+c², a²+c², a²+b²) with m = 2; about the origin its products are ∫xy dm = m·1·0.5
    # and the tensor's entry is minus that (trimesh's sign).
    v = np.array([[x, y, z] for x in (0.0, 2.0) for y in (0.0, 1.0) for z in (0.0, 1.0)])
    quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    box = pgamesh.Mesh(v, quads)
    assert math.isclose(box.volume, 2.0, rel_tol=1e-15)
    np.testing.assert_allclose(box.center_mass, [1.0, 0.5, 0.5], rtol=1e-15)
    np.testing.assert_allclose(box.moment_inertia, np.diag([2 / 12 * 2, 2 / 12 * 5, 2 / 12 * 5]),
                               atol=1e-15)
    origin = box.mass_properties()["inertia_origin"]
    assert math.isclose(origin[0, 1], -(2 * 1.0 * 0.5), rel_tol=1e-14)
    assert origin[0, 0] > 0
    np.testing.assert_allclose(box.principal_inertia_components, [2 / 12 * 2, 2 / 12 * 5, 2 / 12 * 5],
                               rtol=1e-14)
