"""The Dask batch: a LocalCluster over meshes and hostile files, a worker killed mid-run, resuming."""

import csv
import json
import os
import signal
import subprocess
import sys

import pytest

import pgamesh
from pgamesh.batch import COLUMNS, analyse, expand, run_batch
from conftest import BUNDLED, REPO

distributed = pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture
def files(tmp_path):
    """The bundled meshes, copies of them, and hostile files."""
    folder = tmp_path / "in"
    folder.mkdir()
    out = []
    for i in range(3):
        for src in BUNDLED:
            dst = folder / f"{i}_{src.name}"
            dst.write_bytes(src.read_bytes())
            out.append(dst)
    hostile = {
        "empty.stl": b"",
        "garbage.obj": b"\x00\xff\x13garbage\nf 1 2 3\n",
        "truncated.stl": b"\0" * 80 + (10 ** 6).to_bytes(4, "little") + b"\0" * 60,
        "huge_count.ply": b"ply\nformat ascii 1.0\nelement vertex 99999999999999\nproperty float x\n"
                          b"end_header\n",
        "bad_index.off": b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
    }
    for name, data in hostile.items():
        (folder / name).write_bytes(data)
        out.append(folder / name)
    return sorted(str(p) for p in out), set(str(folder / n) for n in hostile)


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_rows(rows, paths, hostile):
    assert sorted(r["path"] for r in rows) == sorted(paths)  # every file once, none twice
    for r in rows:
        if r["path"] in hostile:
            assert r["error"], r["path"]
        else:
            assert not r["error"], r["error"]
            doc = pgamesh.analyze_file(r["path"])
            assert float(r["volume"]) == doc["volume"]
            assert float(r["inertia_xy"]) == doc["inertia_com"][0][1]
            assert int(r["triangles"]) == doc["triangles"]


def test_batch_with_hostile_files_then_resume(client, files, tmp_path):
    paths, hostile = files
    out = str(tmp_path / "results.csv")
    first = run_batch(paths[:5], out, client, progress=False)
    assert first["written"] == 5
    counts = run_batch(paths, out, client, progress=False)
    assert counts["skipped"] == 5 and counts["written"] == len(paths) - 5
    assert counts["errors"] == len(hostile & set(paths[5:]))
    check_rows(read_rows(out), paths, hostile)
    # Nothing left to do; a changed file is analysed again.
    assert run_batch(paths, out, client, progress=False)["written"] == 0
    st = os.stat(paths[0])
    os.utime(paths[0], ns=(st.st_atime_ns, st.st_mtime_ns + 10 ** 9))
    assert run_batch(paths, out, client, progress=False)["written"] == 1


def test_interrupted_line_is_dropped_on_resume(client, files, tmp_path):
    paths, hostile = files
    out = tmp_path / "results.jsonl"
    run_batch(paths, str(out), client, progress=False)
    lines = out.read_bytes().splitlines(keepends=True)
    out.write_bytes(b"".join(lines[:-1]) + lines[-1][:10])  # a run killed mid-write
    counts = run_batch(paths, str(out), client, progress=False)
    assert counts["written"] == 1
    rows = [json.loads(line) for line in out.read_text().splitlines()]
    assert sorted(r["path"] for r in rows) == sorted(paths)


def kill_worker_on(victim, marker):
    """A task that kills its own worker process (SIGKILL) the first time it meets `victim`."""

    def task(path, size, mtime_ns, **options):
        if os.path.basename(path) == victim:
            try:
                os.close(os.open(marker, os.O_CREAT | os.O_EXCL))
                os.kill(os.getpid(), signal.SIGKILL)
            except FileExistsError:
                pass
        return analyse(path, size, mtime_ns, **options)

    return task


@pytest.mark.parametrize("files_per_task", [1, 3])
def test_killed_worker_loses_and_duplicates_nothing(client, files, tmp_path, files_per_task):
    paths, hostile = files
    out = str(tmp_path / "results.csv")
    marker = str(tmp_path / "killed")
    victim = os.path.basename(paths[len(paths) // 2])
    counts = run_batch(paths, out, client, progress=False, files_per_task=files_per_task,
                       task=kill_worker_on(victim, marker))
    assert os.path.exists(marker)  # a worker did die
    assert counts["written"] == len(paths)
    check_rows(read_rows(out), paths, hostile)
    client.wait_for_workers(2, timeout=60)  # the nanny restarted it


def test_expand_globs_and_unmatched_patterns():
    files, unmatched = expand([str(REPO / "data/meshes/*.stl"), str(REPO / "data/**/tank.obj"),
                               str(REPO / "data/meshes/bunny.stl"), "no/such/*.stl"])
    assert files == sorted({str(REPO / "data/meshes/bunny.stl"), str(REPO / "data/meshes/tank.obj")})
    assert unmatched == ["no/such/*.stl"]


def test_command_line(tmp_path):
    out = tmp_path / "r.csv"
    p = subprocess.run([sys.executable, "-m", "pgamesh", "batch", str(REPO / "data/meshes/*.stl"),
                        str(REPO / "data/meshes/*.obj"), "--out", str(out), "--workers", "1",
                        "--fuel-table", "4", "--up", "0,0,1", "--no-progress"],
                       capture_output=True, text=True, timeout=100)
    rows = read_rows(out)
    assert len(rows) == len(BUNDLED), p.stderr
    tank = [r for r in rows if r["path"].endswith("tank.obj")][0]
    assert not tank["error"] and len(json.loads(tank["fuel_table"])["level"]) == 5
    assert list(rows[0].keys()) == list(COLUMNS)
