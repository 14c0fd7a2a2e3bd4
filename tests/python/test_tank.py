"""pgamesh.Tank against `pgamesh fuel --json` on the bundled tank."""

import math

import numpy as np
import pytest

import pgamesh
from conftest import run_cli

TANK = "data/meshes/tank.obj"


@pytest.fixture(scope="module")
def tank():
    return pgamesh.Tank(pgamesh.load(TANK))


def test_fuel_at_a_level_is_the_cli_document(cli, tank):
    code, doc, _ = run_cli(cli, "fuel", TANK, "--up", "0,0,1", "--level", "0.3", "--json")
    assert code == 0
    state = tank.fuel((0, 0, 1), level=0.3)
    for field, value in state.items():
        assert doc[field] == value, field


def test_volume_and_fraction_find_the_level(cli, tank):
    code, doc, _ = run_cli(cli, "fuel", TANK, "--up", "0,0,1", "--volume", "0.5", "--json")
    assert code == 0
    state = tank.fuel((0, 0, 1), volume=0.5)
    assert state["level"] == doc["level"] and state["volume"] == doc["volume"]
    assert tank.level_for_volume((0, 0, 1), 0.5) == doc["level"]
    half = tank.fuel((0, 0, 1), fraction=0.5)
    assert math.isclose(half["volume"], tank.volume / 2, rel_tol=1e-12)


def test_table_is_the_cli_table(cli, tank):
    code, doc, _ = run_cli(cli, "fuel", TANK, "--up", "0,0,1", "--table", "20", "--json")
    assert code == 0
    table = tank.table((0, 0, 1), 20)
    assert table["level"].shape == (21,) and table["center_mass"].shape == (21, 3)
    assert table["level"].tolist() == [r["level"] for r in doc["rows"]]
    assert table["volume"].tolist() == [r["volume"] for r in doc["rows"]]
    assert table["volume"][0] == 0 and math.isclose(table["volume"][-1], tank.volume, rel_tol=1e-13)


def test_attitude_grid(cli, tank):
    grid = tank.attitudes([0, 5], [-2, 0, 2], volume=0.5)
    assert grid["level"].shape == (2, 3) and grid["up"].shape == (2, 3, 3)
    np.testing.assert_allclose(grid["volume"], 0.5, rtol=1e-12)
    code, doc, _ = run_cli(cli, "fuel", TANK, "--up", "0,0,1", "--pitch", "5", "--roll", "-2",
                           "--volume", "0.5", "--json")
    assert code == 0
    assert grid["level"][1, 0] == doc["level"]


def test_open_mesh_is_refused():
    v = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ValueError, match="not a valid tank"):
        pgamesh.Tank(pgamesh.Mesh(v, [[0, 2, 1], [0, 1, 3]]))
