"""numpy round trips, views without copies, and the validation of arrays."""

import numpy as np
import pytest

import pgamesh

# The unit right tetrahedron: volume 1/6, area 3/2 + √3/2, centre of mass (1/4, 1/4, 1/4).
TET_V = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
TET_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def test_round_trip_and_closed_forms():
    mesh = pgamesh.Mesh(TET_V, TET_F)
    np.testing.assert_array_equal(mesh.vertices, TET_V)
    np.testing.assert_array_equal(mesh.faces, TET_F)
    assert mesh.faces.dtype == np.uint32 and mesh.faces.shape == (4, 3)
    assert mesh.vertices.dtype == np.float64 and mesh.vertices.shape == (4, 3)
    assert abs(mesh.volume - 1 / 6) < 1e-16
    assert abs(mesh.area - (1.5 + np.sqrt(3) / 2)) < 1e-15
    np.testing.assert_allclose(mesh.center_mass, [0.25] * 3, rtol=1e-15)
    assert mesh.is_watertight and mesh.is_winding_consistent and mesh.is_volume
    assert mesh.gap_area == 0


def test_views_share_memory_and_are_read_only():
    mesh = pgamesh.Mesh(TET_V, TET_F)
    a, b = mesh.vertices, mesh.vertices
    assert np.shares_memory(a, b)  # both views of the mesh's own array: no copy
    assert np.shares_memory(mesh.faces, mesh.corners)
    assert not a.flags.writeable and not mesh.faces.flags.writeable
    with pytest.raises(ValueError):
        a[0, 0] = 5.0
    del mesh  # the view keeps the mesh alive
    np.testing.assert_array_equal(a, TET_V)


def test_polygons_of_any_size():
    v = np.array([[x, y, z] for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)])
    quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    cube = pgamesh.Mesh(v, quads)
    assert cube.volume == 1.0 and cube.area == 6.0
    assert isinstance(cube.faces, list) and [list(f) for f in cube.faces] == quads
    np.testing.assert_array_equal(cube.face_offsets, np.arange(0, 25, 4))
    mixed = pgamesh.Mesh(TET_V, [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    assert mixed.volume == pgamesh.Mesh(TET_V, TET_F).volume


def test_open_mesh_gap_and_loops():
    # The tetrahedron without its slanted face: the gap is that face's area √3/2 and the one
    # boundary loop runs around it.
    mesh = pgamesh.Mesh(TET_V, TET_F[:3])
    assert not mesh.is_watertight and not mesh.is_volume
    assert abs(mesh.gap_area - np.sqrt(3) / 2) < 1e-15
    loops = mesh.boundary_loops
    assert len(loops) == 1 and sorted(loops[0]["vertices"].tolist()) == [1, 2, 3]
    assert abs(loops[0]["perimeter"] - 3 * np.sqrt(2)) < 1e-14


@pytest.mark.parametrize("vertices, faces, message", [
    (np.zeros((4, 2)), TET_F, "shape"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0], [0, 0, 1.0]]), TET_F, "row 2"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.inf, 0], [0, 0, 1.0]]), TET_F, "row 2"),
    (TET_V, np.array([[0, 1, 2], [0, 1, 4]]), "faces row 1"),
    (TET_V, np.array([[0, 1, 2], [0, -1, 3]]), "faces row 1"),
    (TET_V, [[0, 1, 2], [0, 1]], "faces row 1"),
    (TET_V, [[0, 1, 2], [0, 1, 9, 3]], "faces row 1"),
    (TET_V, np.array([[0.0, 1.0, 2.0]]), "integer"),
])
def test_bad_arrays_name_the_row(vertices, faces, message):
    with pytest.raises(ValueError, match=message):
        pgamesh.Mesh(vertices, faces)


def test_long_calls_release_the_gil():
    # A thread counts while the main thread reads and analyses a 50,000-triangle binary STL: with
    # the GIL held through the C++ calls it could not count meanwhile.
    import struct
    import threading
    import time

    n = 50_000
    records = np.zeros(n, dtype=[("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    rng = np.random.default_rng(0)
    records["v"] = rng.random((n, 3, 3), dtype=np.float32)
    data = b"\0" * 80 + struct.pack("<I", n) + records.tobytes()
    count, done = [0], threading.Event()

    def counter():
        while not done.is_set():
            count[0] += 1

    thread = threading.Thread(target=counter)
    thread.start()
    try:
        # The counting rate while the main thread waits (time.sleep releases the GIL) ...
        start, before = time.perf_counter(), count[0]
        time.sleep(0.2)
        rate = (count[0] - before) / (time.perf_counter() - start)
        # ... and the count while it is inside the C++ calls. Held, the GIL would let the counter
        # run only at the few switches between the calls (5 ms each, sys.getswitchinterval()).
        start, before = time.perf_counter(), count[0]
        while time.perf_counter() - start < 0.3:  # long enough for the switches not to count
            mesh = pgamesh.load(data)
            _ = mesh.volume, mesh.is_watertight
        elapsed, during = time.perf_counter() - start, count[0] - before
    finally:
        done.set()
        thread.join()
    assert mesh.triangles == n
    assert during > 0.25 * rate * elapsed


def test_load_bytes_equals_load_path():
    data = open("data/meshes/bunny.stl", "rb").read()
    a, b = pgamesh.load(data), pgamesh.load("data/meshes/bunny.stl")
    assert a.volume == b.volume and np.array_equal(a.moment_inertia, b.moment_inertia)
    c = pgamesh.Mesh(b.vertices, b.faces)
    assert c.volume == b.volume  # the arrays round-trip to the same figures, bit for bit


def test_pickle_round_trip():
    import pickle

    mesh = pgamesh.load("data/meshes/tank.obj")
    copy = pickle.loads(pickle.dumps(mesh))
    np.testing.assert_array_equal(copy.vertices, mesh.vertices)
    np.testing.assert_array_equal(copy.face_offsets, mesh.face_offsets)
    assert copy.format == mesh.format and copy.props() == mesh.props()
