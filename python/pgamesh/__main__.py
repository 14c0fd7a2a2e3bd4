"""``python3 -m pgamesh batch PATHS_OR_GLOBS... --out FILE``: mesh files analysed as Dask tasks.

See :mod:`pgamesh.batch` and docs/python.md. Exit status: 0 when every file has a row (files that
failed included: their rows say why), 1 when a file failed, 2 for bad usage.
"""

from __future__ import annotations

import argparse
import os
import sys
from typing import Optional, Sequence


def _vector(text: str) -> tuple:
    parts = text.split(",")
    if len(parts) != 3:
        raise argparse.ArgumentTypeError("expected X,Y,Z")
    return tuple(float(p) for p in parts)


def _positive(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 1, not {text!r}")
    return value


def parser() -> argparse.ArgumentParser:
    """The command line of ``python3 -m pgamesh``."""
    p = argparse.ArgumentParser(prog="python3 -m pgamesh",
                                description="pgamesh from Python (docs/python.md).")
    sub = p.add_subparsers(dest="command", required=True)
    b = sub.add_parser(
        "batch", help="analyse many mesh files as Dask tasks, one row per file",
        description="Analyses every file (the figures of `pgamesh props --json`) in Dask "
                    "tasks and appends one row per file to --out (CSV, or JSON Lines for .jsonl). "
                    "Files already in --out (same path, size and mtime) are skipped; a failing "
                    "file records its error.")
    b.add_argument("paths", nargs="+", metavar="PATH_OR_GLOB",
                   help="files or globs ('**' recursive; quote it)")
    b.add_argument("--out", required=True, help="results file: .csv or .jsonl")
    b.add_argument("--scheduler", help="address of a running scheduler, tcp://HOST:PORT "
                                       "(default: a LocalCluster on this machine)")
    b.add_argument("--workers", type=int, default=None,
                   help="LocalCluster workers, of one thread each, in this process (default: "
                        "the number of cores)")
    b.add_argument("--processes", action="store_true",
                   help="LocalCluster of --workers worker processes instead: a file that "
                        "crashes the analysis takes down only its worker")
    b.add_argument("--density", type=float, help="mass per unit volume (default 1)")
    b.add_argument("--weld-tolerance", type=float,
                   help="weld vertices closer than T for the topology (default: exact)")
    b.add_argument("--fuel-table", type=int, metavar="N",
                   help="also a gauge table of N + 1 levels per file (closed meshes)")
    b.add_argument("--up", type=_vector, default=(0.0, 0.0, 1.0), metavar="X,Y,Z",
                   help="up vector of the fuel table (default 0,0,1)")
    b.add_argument("--group", type=_positive, metavar="N",
                   help="files analysed by one Dask task (default: about 16 tasks per worker "
                        "thread, at most 64 files and 8 MB a task; 1 file a task for a small "
                        "batch)")
    b.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    return p


def batch(args: argparse.Namespace) -> int:
    """Runs the batch command; returns the exit status."""
    from distributed import Client

    from .batch import expand, local_cluster, run_batch

    files, unmatched = expand(args.paths)
    for pattern in unmatched:
        print(f"pgamesh batch: no file matches {pattern}", file=sys.stderr)
    if not files:
        return 1
    if args.scheduler:
        cluster = None
        client = Client(args.scheduler)
    else:
        workers = args.workers or os.cpu_count() or 1
        cluster = local_cluster(workers, processes=args.processes)
        client = Client(cluster)
    try:
        counts = run_batch(files, args.out, client, density=args.density,
                           weld_tolerance=args.weld_tolerance, fuel_table=args.fuel_table,
                           up=args.up, progress=not args.no_progress,
                           group=args.group)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    print(f"pgamesh batch: {counts['files']} files, {counts['skipped']} already in {args.out}, "
          f"{counts['written']} rows written, {counts['errors']} errors", file=sys.stderr)
    return 1 if counts["errors"] or unmatched else 0


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Entry point of ``python3 -m pgamesh``."""
    args = parser().parse_args(argv)
    if args.command == "batch":
        return batch(args)
    return 2


if __name__ == "__main__":
    sys.exit(main())
