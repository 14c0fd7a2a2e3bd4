"""The Dask batch: a LocalCluster over meshes and hostile files, a worker killed mid-run, resuming."""

import csv
import json
import os
import signal
import subprocess
import sys
import time

import pytest

import pgamesh
from pgamesh.batch import (COLUMNS, GROUP_BYTES, analyse, expand, local_cluster, make_groups,
                           run_batch)
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


# group=None: the automatic choice, one file a task for so few files; 4: groups holding hostile
# files among good ones.
@pytest.mark.parametrize("group", [None, 4])
def test_batch_with_hostile_files_then_resume(client, files, tmp_path, capsys, group):
    paths, hostile = files
    out = str(tmp_path / "results.csv")
    first = run_batch(paths[:5], out, client, progress=False, group=group)
    assert first["written"] == 5
    counts = run_batch(paths, out, client, progress=True, group=group)
    assert counts["skipped"] == 5 and counts["written"] == len(paths) - 5
    assert counts["errors"] == len(hostile & set(paths[5:]))
    check_rows(read_rows(out), paths, hostile)
    # The progress bar counts files, not tasks.
    last = capsys.readouterr().err.strip().splitlines()[-1]
    assert f" {len(paths) - 5}/{len(paths) - 5} files, {counts['errors']} errors" in last
    # Nothing left to do; a changed file is analysed again.
    assert run_batch(paths, out, client, progress=False, group=group)["written"] == 0
    st = os.stat(paths[0])
    os.utime(paths[0], ns=(st.st_atime_ns, st.st_mtime_ns + 10 ** 9))
    assert run_batch(paths, out, client, progress=False, group=group)["written"] == 1


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


def data_rows(out):
    """The rows in a results file being written (the header and a partial line not counted)."""
    try:
        with open(out, newline="") as f:
            return max(0, f.read().count("\n") - 1)
    except FileNotFoundError:
        return 0


def kill_worker_on(victim, marker, out):
    """A task that kills its own worker process (SIGKILL) the first time it meets `victim`, once
    the client has written some rows (so mid-run): `marker` records how many."""

    def task(path, size, mtime_ns, **options):
        if os.path.basename(path) == victim and not os.path.exists(marker):
            for _ in range(500):  # up to 10 s for another task's rows
                if data_rows(out) > 0:
                    break
                time.sleep(0.02)
            try:
                fd = os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
            except FileExistsError:
                pass
            else:
                os.write(fd, str(data_rows(out)).encode())
                os.close(fd)
                os.kill(os.getpid(), signal.SIGKILL)
        return analyse(path, size, mtime_ns, **options)

    return task


@pytest.mark.parametrize("group", [1, 3])
def test_killed_worker_loses_and_duplicates_nothing(client, files, tmp_path, group):
    paths, hostile = files
    out = str(tmp_path / "results.csv")
    marker = str(tmp_path / "killed")
    victim = os.path.basename(paths[len(paths) // 2])
    counts = run_batch(paths, out, client, progress=False, group=group,
                       task=kill_worker_on(victim, marker, out))
    with open(marker) as f:  # a worker did die, mid-run: rows before, the victim's group after
        rows_at_kill = int(f.read())
    assert 0 < rows_at_kill <= len(paths) - group
    assert counts["written"] == len(paths)
    check_rows(read_rows(out), paths, hostile)
    client.wait_for_workers(2, timeout=60)  # the nanny restarted it


def raise_on(victim):
    """A task that raises (not a row with an error: the whole Dask task fails) on `victim`."""

    def task(path, size, mtime_ns, **options):
        if os.path.basename(path) == victim:
            raise RuntimeError("a task that failed as a whole")
        return analyse(path, size, mtime_ns, **options)

    return task


def test_failed_group_is_retried_file_by_file(client, files, tmp_path):
    paths, hostile = files
    out = str(tmp_path / "results.csv")
    victim = paths[1]  # in the first group of 4, with good and (further on) hostile files
    counts = run_batch(paths, out, client, progress=False, group=4,
                       task=raise_on(os.path.basename(victim)))
    assert counts["written"] == len(paths)
    assert counts["errors"] == len(hostile) + 1
    rows = read_rows(out)
    assert [r["error"] for r in rows if r["path"] == victim] == [
        "RuntimeError: a task that failed as a whole"]
    check_rows([r for r in rows if r["path"] != victim], [p for p in paths if p != victim],
               hostile)


def test_groups_are_consecutive_and_bounded():
    small = [(f"f{i}", 1000, 0) for i in range(100)]
    # 2 threads, 16 groups each at least: 100 // 32 = 3 files a group.
    groups = make_groups(small, threads=2)
    assert [len(g) for g in groups] == [3] * 33 + [1]
    assert [k for g in groups for k in g] == small
    assert [len(g) for g in make_groups(small, threads=2, group=40)] == [40, 40, 20]
    assert [len(g) for g in make_groups(small[:5], threads=2)] == [1] * 5
    assert [len(g) for g in make_groups(small * 100, threads=1)] == [64] * 156 + [16]
    # By bytes: files of 3/8 of the limit go two a group (64 files would allow 4), and a file
    # above the limit is alone.
    big = [(f"b{i}", GROUP_BYTES * 3 // 8, 0) for i in range(63)]
    mixed = big[:31] + [("huge", GROUP_BYTES * 2, 0)] + big[31:]
    groups = make_groups(mixed, threads=1)
    assert [len(g) for g in groups] == [2] * 15 + [1, 1] + [2] * 16
    assert groups[16] == [("huge", GROUP_BYTES * 2, 0)]
    assert [k for g in groups for k in g] == mixed
    with pytest.raises(ValueError):
        make_groups(small, threads=2, group=0)


def test_threaded_local_cluster_with_groups(files, tmp_path):
    """The command's default cluster: workers of one thread each in this process."""
    paths, hostile = files
    out = str(tmp_path / "results.jsonl")
    with local_cluster(2) as cluster, distributed.Client(cluster) as c:
        workers = c.scheduler_info()["workers"].values()
        assert len(workers) == 2 and all(w["nthreads"] == 1 for w in workers)
        counts = run_batch(paths, out, c, progress=False, group=3)
    assert counts["written"] == len(paths) and counts["errors"] == len(hostile)
    with open(out) as f:
        rows = [{k: ("" if v is None else v) for k, v in json.loads(line).items()} for line in f]
    check_rows(rows, paths, hostile)


def test_expand_globs_and_unmatched_patterns():
    files, unmatched = expand([str(REPO / "data/meshes/*.stl"), str(REPO / "data/**/tank.obj"),
                               str(REPO / "data/meshes/bunny.stl"), "no/such/*.stl"])
    assert files == sorted({str(REPO / "data/meshes/bunny.stl"), str(REPO / "data/meshes/tank.obj")})
    assert unmatched == ["no/such/*.stl"]


def test_command_line(tmp_path):
    out = tmp_path / "r.csv"
    p = subprocess.run([sys.executable, "-m", "pgamesh", "batch", str(REPO / "data/meshes/*.stl"),
                        str(REPO / "data/meshes/*.obj"), "--out", str(out), "--workers", "1",
                        "--fuel-table", "4", "--up", "0,0,1", "--group", "2", "--no-progress"],
                       capture_output=True, text=True, timeout=100)
    rows = read_rows(out)
    assert len(rows) == len(BUNDLED), p.stderr
    tank = [r for r in rows if r["path"].endswith("tank.obj")][0]
    assert not tank["error"] and len(json.loads(tank["fuel_table"])["level"]) == 5
    assert list(rows[0].keys()) == list(COLUMNS)
