"""Batches of mesh files on Dask: ``python3 -m pgamesh batch PATHS_OR_GLOBS... --out FILE``.

The files are analysed in Dask tasks of a group of files each (``--group N``; by default about
16 groups per worker thread, at most 64 files and 8 MB a group): a Dask task costs the scheduler
and the client a few milliseconds, more than a small part's analysis. Each file's row holds the
figures of :func:`pgamesh.analyze_file` (``pgamesh props --json``); the client writes a group's
rows to the output (CSV or JSON Lines, by the extension) when its task completes, and flushes
them. So:

* a file that fails records its error in the ``error`` column and the batch goes on (a group
  whose task fails as a whole, its worker killed again and again, is retried file by file, so
  only the file at fault records the error);
* re-running with the same ``--out`` skips the files already in it, keyed by path, size and
  modification time (a file that changed is analysed again);
* a worker killed mid-run loses nothing: the scheduler runs its tasks again elsewhere, and since
  only the client writes, and it writes a task's rows once, when its future completes, no row
  appears twice.

docs/python.md shows it on a LocalCluster and on a cluster of ``dask-scheduler`` and
``dask-worker`` processes (``--scheduler tcp://HOST:PORT``).
"""

from __future__ import annotations

import csv
import glob
import io
import json
import os
import sys
import time
from typing import Any, Callable, Dict, Iterable, List, Optional, Sequence, Set, Tuple

#: The columns of a result row, in the order the CSV writes them.
COLUMNS: Tuple[str, ...] = (
    "path", "size", "mtime_ns", "format", "triangles", "closed", "volume", "area",
    "center_mass_x", "center_mass_y", "center_mass_z",
    "inertia_xx", "inertia_xy", "inertia_xz", "inertia_yy", "inertia_yz", "inertia_zz",
    "principal_1", "principal_2", "principal_3", "gap_area", "weld_tolerance", "density", "mass",
    "fuel_table", "error",
)

Key = Tuple[str, int, int]


def expand(patterns: Iterable[str]) -> Tuple[List[str], List[str]]:
    """The files the patterns name: each pattern a path or a glob (``**`` recursive).

    Returns (files, unmatched): the absolute paths in sorted order without duplicates, and the
    patterns that named nothing.
    """
    files: Set[str] = set()
    unmatched: List[str] = []
    for pattern in patterns:
        matches = [pattern] if os.path.isfile(pattern) else glob.glob(pattern, recursive=True)
        matches = [m for m in matches if os.path.isfile(m)]
        if not matches:
            unmatched.append(pattern)
        files.update(os.path.abspath(m) for m in matches)
    return sorted(files), unmatched


def file_key(path: str) -> Key:
    """(path, size, mtime_ns): what identifies a file already done."""
    st = os.stat(path)
    return (path, st.st_size, st.st_mtime_ns)


def analyse(path: str, size: int, mtime_ns: int, density: Optional[float] = None,
            weld_tolerance: Optional[float] = None, fuel_table: Optional[int] = None,
            up: Sequence[float] = (0.0, 0.0, 1.0)) -> Dict[str, Any]:
    """One file's row (runs on a worker). Never raises for a bad file: its error is the row's.

    The figures are :func:`pgamesh.analyze_file`'s (the CLI's JSON) on one thread, since the
    batch's parallelism is across files. With ``fuel_table`` the row also holds the gauge table
    of ``Tank(mesh).table(up, fuel_table)`` as JSON (level, volume per row).
    """
    import pgamesh  # imported on the worker

    row: Dict[str, Any] = {c: None for c in COLUMNS}
    row.update(path=path, size=size, mtime_ns=mtime_ns, weld_tolerance=weld_tolerance or 0.0,
               error="")
    try:
        doc = pgamesh.analyze_file(path, density=density, weld_tolerance=weld_tolerance,
                                   threads=1)
        row.update(format=doc["format"], triangles=doc["triangles"], closed=doc["closed"],
                   volume=doc["volume"], area=doc["area"], gap_area=doc["gap_area"],
                   density=doc["density"], mass=doc["mass"])
        com = doc["center_of_mass"] or [None] * 3
        row.update(center_mass_x=com[0], center_mass_y=com[1], center_mass_z=com[2])
        inertia = doc["inertia_com"] or [[None] * 3] * 3
        for name, (i, j) in (("xx", (0, 0)), ("xy", (0, 1)), ("xz", (0, 2)), ("yy", (1, 1)),
                             ("yz", (1, 2)), ("zz", (2, 2))):
            row["inertia_" + name] = inertia[i][j]
        moments = doc["principal_moments"] or [None] * 3
        row.update(principal_1=moments[0], principal_2=moments[1], principal_3=moments[2])
        if fuel_table:
            mesh = pgamesh.load(path, weld_tolerance=weld_tolerance)
            table = pgamesh.Tank(mesh).table(tuple(up), fuel_table)
            row["fuel_table"] = json.dumps({"level": table["level"].tolist(),
                                            "volume": table["volume"].tolist()})
    except Exception as e:  # a bad file, or a tank that is not one: recorded, the batch goes on
        row["error"] = f"{type(e).__name__}: {e}"
    return row


class RowWriter:
    """Appends rows to a CSV or JSON Lines file, a line per row, flushed after each group.

    Opening an existing file reads the keys of the rows it holds (:attr:`done`); a last line cut
    short by an interrupted run is removed first.
    """

    def __init__(self, path: str) -> None:
        self.path = path
        self.jsonl = path.endswith(".jsonl") or path.endswith(".json")
        self.done: Set[Key] = set()
        self._drop_partial_line()
        if os.path.exists(path):
            with open(path, newline="", encoding="utf-8") as f:
                for row in self._read(f):
                    try:
                        self.done.add((row["path"], int(row["size"]), int(row["mtime_ns"])))
                    except (KeyError, TypeError, ValueError):
                        continue
        new = not os.path.exists(path) or os.path.getsize(path) == 0
        self._file = open(path, "a", newline="", encoding="utf-8")
        self._csv = None if self.jsonl else csv.writer(self._file)
        if self._csv is not None and new:
            self._csv.writerow(COLUMNS)
            self._file.flush()

    def _drop_partial_line(self) -> None:
        if not os.path.exists(self.path):
            return
        with open(self.path, "rb+") as f:
            data = f.read()
            if data and not data.endswith(b"\n"):
                f.truncate(data.rfind(b"\n") + 1)

    def _read(self, f: io.TextIOBase) -> Iterable[Dict[str, Any]]:
        if self.jsonl:
            for line in f:
                if line.strip():
                    yield json.loads(line)
        else:
            yield from csv.DictReader(f)

    def write(self, rows: Iterable[Dict[str, Any]]) -> Tuple[int, int]:
        """Writes the rows whose files are not done yet, then flushes once; returns (rows
        written, errors among them)."""
        written = errors = 0
        for row in rows:
            key = (row["path"], int(row["size"]), int(row["mtime_ns"]))
            if key in self.done:
                continue
            if self.jsonl:
                self._file.write(json.dumps(row, allow_nan=False, default=str) + "\n")
            else:
                self._csv.writerow([row.get(c) for c in COLUMNS])  # None is written as ""
            self.done.add(key)
            written += 1
            errors += bool(row.get("error"))
        # Flushed, not synced: a killed client leaves every written line in the page cache (a
        # sync per group would cost more than analysing it). close() syncs.
        self._file.flush()
        return written, errors

    def close(self) -> None:
        """Syncs the file to disk and closes it."""
        self._file.flush()
        os.fsync(self._file.fileno())
        self._file.close()


class Progress:
    """A one-line progress bar of files on stderr (redrawn in place on a terminal)."""

    def __init__(self, total: int, enabled: bool = True) -> None:
        self.total, self.done, self.errors = total, 0, 0
        self.enabled = enabled
        self.tty = sys.stderr.isatty()
        self.start = time.monotonic()
        self._last = 0.0

    def step(self, files: int, errors: int) -> None:
        """Counts `files` more files done, `errors` of them failed."""
        self.done += files
        self.errors += errors
        now = time.monotonic()
        if self.enabled and (now - self._last > 0.2 or self.done == self.total):
            self._last = now
            width = 30
            filled = width * self.done // max(self.total, 1)
            line = (f"[{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} files, "
                    f"{self.errors} errors, {now - self.start:.1f} s")
            sys.stderr.write(("\r" + line) if self.tty else (line + "\n"))
            if self.tty and self.done == self.total:
                sys.stderr.write("\n")
            sys.stderr.flush()


#: The most files and bytes an automatic group holds: enough that a Dask task (a few
#: milliseconds of the scheduler's and the client's time) costs little next to the analysis, few
#: enough that the last groups still spread over the workers (docs/python.md, "Batches on Dask").
GROUP_FILES = 64
GROUP_BYTES = 8 << 20
#: An automatic group is small enough that every worker thread gets at least this many groups.
GROUPS_PER_THREAD = 16


def analyse_group(keys: Sequence[Key], task: Callable[..., Dict[str, Any]],
                  **options: Any) -> List[Dict[str, Any]]:
    """The rows of a group of files, each by ``task`` (runs on a worker as one Dask task)."""
    return [task(path, size, mtime_ns, **options) for path, size, mtime_ns in keys]


def make_groups(keys: Sequence[Key], threads: int, group: Optional[int] = None) -> List[List[Key]]:
    """The files split into consecutive groups, one Dask task each.

    With ``group``, groups of that many files. Otherwise at most :data:`GROUP_FILES` files and,
    past the first file, :data:`GROUP_BYTES` bytes a group, and small enough that each of the
    cluster's ``threads`` gets :data:`GROUPS_PER_THREAD` groups (a small batch: one file a task).
    """
    if group is not None:
        if group < 1:
            raise ValueError("a group holds at least one file")
        return [list(keys[i:i + group]) for i in range(0, len(keys), group)]
    most = max(1, min(GROUP_FILES, len(keys) // (GROUPS_PER_THREAD * max(threads, 1))))
    groups: List[List[Key]] = []
    current: List[Key] = []
    size = 0
    for key in keys:
        if current and (len(current) == most or size + key[1] > GROUP_BYTES):
            groups.append(current)
            current, size = [], 0
        current.append(key)
        size += key[1]
    if current:
        groups.append(current)
    return groups


def error_row(key: Key, error: str, weld_tolerance: Optional[float] = None) -> Dict[str, Any]:
    """The row of a file that has no figures, only an error."""
    row: Dict[str, Any] = {c: None for c in COLUMNS}
    row.update(path=key[0], size=key[1], mtime_ns=key[2], weld_tolerance=weld_tolerance or 0.0,
               error=error)
    return row


#: Dask settings of the LocalCluster a batch starts. The workers' statistical profiler, the
#: 20 ms event-loop tick and the system monitor feed a dashboard and diagnostics a batch has no
#: use for; at their defaults they keep an idle 2-worker cluster busy for about 14 % of a core,
#: taken from the analysis (docs/python.md, "Speed").
LOCAL_CLUSTER_CONFIG: Dict[str, Any] = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.worker.memory.monitor-interval": "500ms",
}


def local_cluster(workers: int, processes: bool = False) -> Any:
    """A ``distributed.LocalCluster`` of ``workers`` workers of one thread each, no dashboard,
    :data:`LOCAL_CLUSTER_CONFIG`.

    By default the workers run in this process: the analysis releases the GIL, and no row is
    pickled or sent between processes (on a 2-core machine 2 such workers beat 2 worker processes,
    docs/python.md, "Speed"). With ``processes``, each worker is a process of its own under a
    nanny: a file that crashes its worker's process takes down only that worker, which is
    restarted and its group run again.
    """
    import dask
    from distributed import LocalCluster

    with dask.config.set(LOCAL_CLUSTER_CONFIG):
        if processes:
            return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                dashboard_address=None)
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=False,
                            dashboard_address=None)


def run_batch(paths: Sequence[str], out: str, client: Any, *, density: Optional[float] = None,
              weld_tolerance: Optional[float] = None, fuel_table: Optional[int] = None,
              up: Sequence[float] = (0.0, 0.0, 1.0), progress: bool = True,
              group: Optional[int] = None,
              task: Callable[..., Dict[str, Any]] = analyse) -> Dict[str, int]:
    """Analyses the files on the Dask ``client`` and appends one row per file to ``out``.

    Files whose (path, size, mtime) is already in ``out`` are skipped. The files go to the
    workers in groups, one Dask task each: ``group`` files a task, or :func:`make_groups`'
    automatic choice. A group's rows are written when its task completes, so a task run again
    after its worker died still writes each row once. A task that fails as a whole (its worker
    killed again and again) is split into tasks of one file, so that only the file at fault gets
    the error. ``task`` is the function run per file (default :func:`analyse`). Returns counts:
    files, skipped, written, errors.
    """
    from distributed import as_completed

    writer = RowWriter(out)
    try:
        todo: List[Key] = []
        skipped = written = errors = 0
        for path in paths:
            try:
                key = file_key(path)
            except OSError as e:
                new, failed = writer.write([error_row((path, -1, -1), f"OSError: {e}")])
                written += new
                errors += failed
                continue
            if key in writer.done:
                skipped += 1
            else:
                todo.append(key)
        threads = sum(w.get("nthreads", 1)
                      for w in client.scheduler_info().get("workers", {}).values())
        groups = make_groups(todo, threads, group)
        options = dict(density=density, weld_tolerance=weld_tolerance, fuel_table=fuel_table,
                       up=tuple(up))
        bar = Progress(len(todo), progress)
        # One call for every group: the client's cost of a submission (it reads the caller's
        # source for the scheduler's records) is paid once, not per task. pure=False: a new run
        # of unchanged files is a new task, never a stale result.
        futures = client.map(analyse_group, groups, task=task, pure=False, **options)
        pending = dict(zip(futures, groups))
        completed = as_completed(futures)
        for future in completed:
            keys = pending.pop(future)
            try:
                rows = future.result()
            except Exception as e:  # the task itself died (its worker killed too often)
                if len(keys) > 1:
                    for key in keys:
                        single = client.submit(analyse_group, [key], task, pure=False, **options)
                        pending[single] = [key]
                        completed.add(single)
                    future.release()
                    continue
                rows = [error_row(keys[0], f"{type(e).__name__}: {e}", weld_tolerance)]
            future.release()
            new, failed = writer.write(rows)
            written += new
            errors += failed
            bar.step(len(rows), sum(bool(r.get("error")) for r in rows))
        return {"files": len(paths), "skipped": skipped, "written": written, "errors": errors}
    finally:
        writer.close()
