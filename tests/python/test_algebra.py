"""pgamesh.pga3 and pgamesh.models against closed forms."""

import math

import numpy as np
import pytest

import pgamesh
from pgamesh import models, pga3


def test_join_of_three_points_is_twice_the_area():
    a, b, c = pga3.point(1, 0, 0), pga3.point(0, 1, 0), pga3.point(0, 0, 1)
    carrier = a & b & c
    assert math.isclose(carrier.norm() / 2, math.sqrt(3) / 2, rel_tol=1e-15)
    # The plane x + y + z - 1 = 0, up to its weight.
    co = carrier.coefficients
    assert co[2] == co[3] == co[4] and math.isclose(co[1], -co[2], rel_tol=1e-15)


def test_products_and_reverse():
    e1, e2, e12 = pga3.blade("e1"), pga3.blade("e2"), pga3.blade("e12")
    assert (e1 * e2) == e12 and (e1 ^ e2) == e12
    assert (e12 * e12)["1"] == -1 and (~e12) == -e12
    assert (e1 | e1)["1"] == 1
    with pytest.raises(KeyError):
        e1["e4"]


def test_motor_moves_points():
    quarter = pga3.rotor(math.pi / 2, (0, 0, 1))
    np.testing.assert_allclose(quarter.apply_point((1, 0, 0)), [0, 1, 0], atol=1e-15)
    shift = pga3.translator((1, 2, 3))
    np.testing.assert_allclose((shift * quarter).apply_point((1, 0, 0)), [1, 3, 3], atol=1e-15)
    moved = quarter(pga3.point(1, 0, 0))
    np.testing.assert_allclose(moved.coefficients[11:15], [0, 1, 0, 1], atol=1e-15)


def test_motor_coefficients_in_basis_order():
    # s, e01, e02, e03, e12, e31, e23, e0123, whatever the storage order of the C++ type.
    c = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]
    m = pga3.Motor(c)
    assert list(m.coefficients) == c
    assert (m.s, m.e01, m.e02, m.e03, m.e12, m.e31, m.e23, m.e0123) == tuple(c)
    mv = m.multivector
    assert [mv[k] for k in ("1", "e01", "e02", "e03", "e12", "e31", "e23", "e0123")] == c
    # The composition of two translators adds their shifts, exactly for these values.
    shift = pga3.translator((1, 2, 3)) * pga3.translator((4, 8, 16))
    assert list(shift.coefficients) == [1, -2.5, -5, -9.5, 0, 0, 0, 0]


def test_principal_motor_places_the_frame():
    mesh = pgamesh.load("data/meshes/bunny.stl")
    motor = mesh.principal_motor
    np.testing.assert_allclose(motor.apply_point((0, 0, 0)), mesh.center_mass, rtol=1e-12)
    for i, axis in enumerate(np.eye(3)):
        np.testing.assert_allclose(motor.apply_direction(axis), mesh.principal_inertia_vectors[i],
                                   atol=1e-12)


def test_cga_objects_through_points():
    s = models.sphere_through([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, 0, 1]])
    np.testing.assert_allclose(s["center"], [0, 0, 0], atol=1e-15)
    assert math.isclose(s["radius"], 1, rel_tol=1e-15)
    c = models.circle_through([[2, 0, 5], [0, 2, 5], [-2, 0, 5]])
    assert math.isclose(c["radius"], 2, rel_tol=1e-15)
    np.testing.assert_allclose(c["center"], [0, 0, 5], atol=1e-14)
    p = models.plane_through([[0, 0, 3], [1, 0, 3], [0, 1, 3]])
    assert math.isclose(abs(p["distance"]), 3, rel_tol=1e-15)
    with pytest.raises(ValueError):
        models.sphere_through([[0, 0, 0]])


def test_quadric_sphere():
    q = models.Quadric([1, 1, 1, 0, 0, 0, 0, 0, 0, -4])  # x² + y² + z² = 4
    assert q.value((2, 0, 0)) == 0
    np.testing.assert_array_equal(q.gradient((0, 2, 0)), [0, 4, 0])
    assert q.classify()["type"] == "ellipsoid" or "sphere" in q.classify()["type"]
    rng = np.random.default_rng(1)
    d = rng.normal(size=(30, 3))
    pts = 2 * d / np.linalg.norm(d, axis=1)[:, None]
    fitted = models.Quadric.fit(pts).coefficients
    np.testing.assert_allclose(fitted / fitted[0], q.coefficients, atol=1e-9)
