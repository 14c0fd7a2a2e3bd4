"""Batches of mesh files on Dask: ``python3 -m pgamesh batch PATHS_OR_GLOBS... --out FILE``.

Every file is analysed in a Dask task that runs :func:`pgamesh.analyze_file` (the figures of
``pgamesh props --json``) and returns one row; the client writes the rows to the output (CSV or
JSON Lines, by the extension) as the futures complete, and flushes them. So:

* a file that fails records its error in the ``error`` column and the batch goes on;
* re-running with the same ``--out`` skips the files already in it, keyed by path, size and
  modification time (a file that changed is analysed again);
* a worker killed mid-run loses nothing: the scheduler runs its tasks again elsewhere, and since
  only the client writes, and it writes a task's rows once, when its future completes, no row
  appears twice.

Small files are sent in groups (``--files-per-task``; by default 1 for a small batch, up to 32
for a large one): a Dask task costs the scheduler and the client more than a small part's
analysis.

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
    """Appends rows to a CSV or JSON Lines file, one flushed line per row.

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
        self._csv = None if self.jsonl else csv.DictWriter(self._file, fieldnames=COLUMNS)
        if self._csv is not None and new:
            self._csv.writeheader()
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

    def write(self, row: Dict[str, Any]) -> bool:
        """Writes the row unless its file is already done; returns whether it wrote."""
        key = (row["path"], int(row["size"]), int(row["mtime_ns"]))
        if key in self.done:
            return False
        if self.jsonl:
            self._file.write(json.dumps(row, allow_nan=False, default=str) + "\n")
        else:
            self._csv.writerow({k: ("" if v is None else v) for k, v in row.items()})
        # Flushed, not synced: a killed client leaves every written line in the page cache (a
        # sync per row would cost more than analysing a small part). close() syncs.
        self._file.flush()
        self.done.add(key)
        return True

    def close(self) -> None:
        """Syncs the file to disk and closes it."""
        self._file.flush()
        os.fsync(self._file.fileno())
        self._file.close()


class Progress:
    """A one-line progress bar on stderr (redrawn in place on a terminal)."""

    def __init__(self, total: int, enabled: bool = True) -> None:
        self.total, self.done, self.errors = total, 0, 0
        self.enabled = enabled
        self.tty = sys.stderr.isatty()
        self.start = time.monotonic()
        self._last = 0.0

    def step(self, error: bool) -> None:
        self.done += 1
        self.errors += bool(error)
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


def analyse_group(keys: Sequence[Key], task: Callable[..., Dict[str, Any]],
                  **options: Any) -> List[Dict[str, Any]]:
    """The rows of a group of files, each by ``task`` (runs on a worker as one Dask task)."""
    return [task(path, size, mtime_ns, **options) for path, size, mtime_ns in keys]


def default_files_per_task(files: int, workers: int) -> int:
    """Files per task: 1 for a small batch; for a large one, enough that each worker still gets
    at least 16 tasks (load balance, progress) but at most 32 files a task. A task costs the
    scheduler and the client a few milliseconds, more than analysing a small part."""
    return max(1, min(32, files // (16 * max(workers, 1))))


def run_batch(paths: Sequence[str], out: str, client: Any, *, density: Optional[float] = None,
              weld_tolerance: Optional[float] = None, fuel_table: Optional[int] = None,
              up: Sequence[float] = (0.0, 0.0, 1.0), progress: bool = True,
              files_per_task: Optional[int] = None,
              task: Callable[..., Dict[str, Any]] = analyse) -> Dict[str, int]:
    """Analyses the files on the Dask ``client`` and appends one row per file to ``out``.

    Files whose (path, size, mtime) is already in ``out`` are skipped. The files go to the
    workers in tasks of ``files_per_task`` files (default :func:`default_files_per_task`); the
    rows of a task are written when it completes, so a task run again after its worker died
    still writes each row once. ``task`` is the function run per file (default
    :func:`analyse`). Returns counts: files, skipped, written, errors.
    """
    from distributed import as_completed

    writer = RowWriter(out)
    try:
        todo: List[Key] = []
        skipped = 0
        for path in paths:
            try:
                key = file_key(path)
            except OSError as e:
                row = {c: None for c in COLUMNS}
                row.update(path=path, size=-1, mtime_ns=-1, error=f"OSError: {e}")
                writer.write(row)
                continue
            if key in writer.done:
                skipped += 1
            else:
                todo.append(key)
        if files_per_task is None:
            workers = len(client.scheduler_info().get("workers", {}))
            files_per_task = default_files_per_task(len(todo), workers)
        if files_per_task < 1:
            raise ValueError("files_per_task must be at least 1")
        bar = Progress(len(todo), progress)
        written = errors = 0
        groups = {}
        for first in range(0, len(todo), files_per_task):
            group = todo[first:first + files_per_task]
            # pure=False: a new run of unchanged files is a new task, never a stale result.
            future = client.submit(analyse_group, group, task, density=density,
                                   weld_tolerance=weld_tolerance, fuel_table=fuel_table,
                                   up=tuple(up), pure=False)
            groups[future] = group
        for future in as_completed(list(groups)):
            group = groups.pop(future)
            try:
                rows = future.result()
            except Exception as e:  # the task itself died (its worker killed too often)
                rows = []
                for path, size, mtime_ns in group:
                    row = {c: None for c in COLUMNS}
                    row.update(path=path, size=size, mtime_ns=mtime_ns,
                               weld_tolerance=weld_tolerance or 0.0,
                               error=f"{type(e).__name__}: {e}")
                    rows.append(row)
            future.release()
            for row in rows:
                if writer.write(row):
                    written += 1
                    errors += bool(row.get("error"))
                bar.step(bool(row.get("error")))
        return {"files": len(paths), "skipped": skipped, "written": written, "errors": errors}
    finally:
        writer.close()
