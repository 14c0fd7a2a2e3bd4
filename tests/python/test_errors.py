"""pgamesh.InputError: a ValueError with the file and the position as attributes."""

import pickle

import pytest

import pgamesh


def test_text_error_has_line_and_column(tmp_path):
    path = tmp_path / "bad.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n")
    with pytest.raises(pgamesh.InputError) as info:
        pgamesh.load(str(path))
    e = info.value
    assert isinstance(e, ValueError)
    assert e.file == str(path) and e.line == 4 and e.byte_offset is None
    assert str(e).startswith(f"{path}:4")


def test_binary_error_has_byte_offset():
    # A binary STL header that promises more triangles than the bytes hold.
    data = b"\0" * 80 + (1000).to_bytes(4, "little") + b"\0" * 50
    with pytest.raises(pgamesh.InputError) as info:
        pgamesh.load(data, format="stl")
    e = info.value
    assert e.file == "<bytes>" and e.line is None and isinstance(e.byte_offset, int)


def test_missing_file_and_analyze_file(tmp_path):
    with pytest.raises(pgamesh.InputError) as info:
        pgamesh.analyze_file(str(tmp_path / "none.stl"))
    assert info.value.file == str(tmp_path / "none.stl")


def test_input_error_pickles(tmp_path):
    path = tmp_path / "bad.off"
    path.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(pgamesh.InputError) as info:
        pgamesh.load(str(path))
    copy = pickle.loads(pickle.dumps(info.value))
    assert type(copy) is pgamesh.InputError and copy.file == info.value.file
    assert copy.line == info.value.line


def test_bad_options():
    with pytest.raises(ValueError):
        pgamesh.load("data/meshes/bunny.stl", weld_tolerance=-1)
    with pytest.raises(ValueError):
        pgamesh.load("data/meshes/bunny.stl").mass_properties(density=1, mass=2)
    with pytest.raises(ValueError):
        pgamesh.analyze_file("data/meshes/bunny.stl", format="xyz")
