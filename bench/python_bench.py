#!/usr/bin/env python3
"""Speed of the Python package (docs/python.md, "Speed"): prints one line per measurement.

1. pgamesh.load(path).mass_properties() on a binary STL of about 10^6 triangles against the CLI's
   `pgamesh props` on the same file (the CLI's wall time includes its process start).
2. The same against trimesh 4.x (load + mass_properties), when --trimesh names a folder holding
   the trimesh package (a source snapshot; it needs only numpy; never a project dependency).
3. A batch of --small-files small binary STLs on a LocalCluster of 2 workers against 1 (the
   median of --repeat runs each), and the same analysis in 2 plain forked processes against 1
   (no Dask): the scaling the machine allows at the time.

Usage (from the repository root, after the release build and scripts/install_python.sh):
  python3 bench/python_bench.py [--cli build/release/pgamesh]
      [--gen build/release/bench/pgamesh_gen_mesh] [--trimesh build/peers/trimesh]
      [--triangles 1000000] [--small-files 2000] [--repeat 3] [--only-batch] [--group N] [--processes]
"""

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import pgamesh


def best(function, repeat):
    """The least wall time of `repeat` calls, in seconds."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--cli", default="build/release/pgamesh")
    p.add_argument("--gen", default="build/release/bench/pgamesh_gen_mesh")
    p.add_argument("--trimesh", help="folder holding the trimesh package (put on sys.path)")
    p.add_argument("--triangles", type=int, default=1_000_000)
    p.add_argument("--small-files", type=int, default=2000)
    p.add_argument("--small-triangles", type=int, default=2000)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--only-batch", action="store_true", help="only the batch measurement")
    p.add_argument("--processes", action="store_true",
                   help="the batch's LocalCluster of worker processes (default: threads)")
    p.add_argument("--group", type=int, help="files per Dask task in the batch (default: "
                                             "pgamesh.batch's automatic choice)")
    a = p.parse_args()

    work = tempfile.mkdtemp(prefix="pgamesh-bench-")
    try:
        print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at start; "
              f"python {sys.version.split()[0]}")
        if not a.only_batch:
            single_file(a, work)
        batch(a, work)
        print(f"load average at the end {os.getloadavg()[0]:.2f}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


def single_file(a, work):
    """Measurements 1 and 2: one big file."""
    big = os.path.join(work, "big.stl")
    subprocess.run([a.gen, str(a.triangles), "stl", big], check=True, capture_output=True)
    print(f"input: {big} ({os.path.getsize(big) / 1e6:.1f} MB, "
          f"{pgamesh.load(big).triangles} triangles, binary STL)")

    py = best(lambda: pgamesh.load(big).mass_properties(), a.repeat)
    py_all = best(lambda: (lambda m: (m.volume, m.is_watertight))(pgamesh.load(big)), a.repeat)
    cli = best(lambda: subprocess.run([a.cli, "props", big], check=True, capture_output=True),
               a.repeat)
    cli_fast = best(lambda: subprocess.run([a.cli, "props", big, "--fast"], check=True,
                                           capture_output=True), a.repeat)
    print(f"pgamesh.load().mass_properties()       {py:8.3f} s")
    print(f"pgamesh.load() + volume + topology     {py_all:8.3f} s")
    print(f"pgamesh props (CLI, topology)          {cli:8.3f} s   python/CLI {py_all / cli:.2f}x")
    print(f"pgamesh props --fast (CLI, streamed)   {cli_fast:8.3f} s   python/CLI {py / cli_fast:.2f}x")

    if a.trimesh:
        sys.path.insert(0, os.path.abspath(a.trimesh))
        import trimesh

        def with_trimesh():
            m = trimesh.load(big)
            return m.mass_properties
        tm = best(with_trimesh, a.repeat)
        print(f"trimesh load + mass_properties         {tm:8.3f} s   "
              f"trimesh/pgamesh {tm / py:.1f}x")
        # The same figures: trimesh's inertia convention is pgamesh's (I_xy = -∫xy dm).
        theirs, ours = trimesh.load(big).mass_properties, pgamesh.load(big).mass_properties()
        size = float(np.max(np.ptp(pgamesh.load(big).vertices, axis=0)))
        for name, scale in (("volume", None), ("center_mass", size), ("inertia", None)):
            t, o = np.asarray(theirs[name]), np.asarray(ours[name])
            scale = scale or float(np.max(np.abs(o)))
            print(f"  trimesh vs pgamesh {name}: max |difference| / "
                  f"{'mesh size' if name == 'center_mass' else 'max |value|'} "
                  f"{np.max(np.abs(t - o)) / scale:.1e}")



def analyse_files(paths):
    """The batch's analysis of the files, in this process, without Dask."""
    from pgamesh.batch import analyse, file_key

    for path in paths:
        analyse(*file_key(path))


def plain_processes(paths, processes):
    """Seconds to analyse the files split over `processes` forked processes, without Dask: the
    scaling the machine itself allows, the ceiling of the batch's."""
    import multiprocessing

    context = multiprocessing.get_context("fork")
    jobs = [context.Process(target=analyse_files, args=(paths[i::processes],))
            for i in range(processes)]
    start = time.perf_counter()
    for job in jobs:
        job.start()
    for job in jobs:
        job.join()
    return time.perf_counter() - start


def cpu_seconds():
    """(CPU seconds of this process and its children so far, of the whole machine since boot):
    how much of the cores other work took during a run."""
    import psutil  # a dependency of distributed

    me = psutil.Process()
    ours = sum(me.cpu_times()[:2])
    for child in me.children(recursive=True):
        try:
            ours += sum(child.cpu_times()[:2])
        except psutil.Error:
            pass
    machine = psutil.cpu_times()
    return ours, machine.user + machine.nice + machine.system + machine.irq + machine.softirq


def batch(a, work):
    """Measurement 3: many small files on 1 and 2 workers."""
    from distributed import Client

    from pgamesh.batch import local_cluster, run_batch

    small = os.path.join(work, "small")
    os.mkdir(small)
    seed = os.path.join(small, "seed.stl")
    subprocess.run([a.gen, str(a.small_triangles), "stl", seed], check=True,
                   capture_output=True)
    paths = []
    for i in range(a.small_files):
        path = os.path.join(small, f"part{i:05d}.stl")
        shutil.copyfile(seed, path)
        paths.append(path)
    os.remove(seed)
    # The runs alternate between 1 and 2 workers, so that other work on the machine weighs on
    # both alike; each is timed from the first submission to the last row written (the cluster's
    # start excluded, the workers' import of pgamesh included), into a new results file.
    times = {1: [], 2: []}
    plain = {1: [], 2: []}
    kind = "process(es)" if a.processes else "(in this process)"
    for run in range(a.repeat):
        for processes in (1, 2):
            plain[processes].append(plain_processes(paths, processes))
        print(f"run {run + 1}: the same files in 1 / 2 plain processes (no Dask): "
              f"{plain[1][-1]:.2f} s / {plain[2][-1]:.2f} s, {plain[1][-1] / plain[2][-1]:.2f}x")
        for workers in (1, 2):
            with local_cluster(workers, processes=a.processes) as cluster, Client(cluster) as client:
                client.submit(lambda: 0).result()  # workers up
                out = os.path.join(work, f"batch{workers}-{run}.csv")
                load = os.getloadavg()[0]
                before = cpu_seconds()
                start = time.perf_counter()
                counts = run_batch(paths, out, client, progress=False, group=a.group)
                times[workers].append(time.perf_counter() - start)
                ours, everyone = (b - a for a, b in zip(before, cpu_seconds()))
                assert counts["written"] == len(paths) and counts["errors"] == 0
            print(f"run {run + 1}: batch of {len(paths)} files x {a.small_triangles} triangles, "
                  f"{workers} worker {kind}: {times[workers][-1]:7.2f} s "
                  f"({len(paths) / times[workers][-1]:.0f} files/s), load average {load:.2f}; "
                  f"CPU s: the batch's processes {ours:.2f}, other work {everyone - ours:.2f}")
    one, two = statistics.median(times[1]), statistics.median(times[2])
    print(f"batch median of {a.repeat}, worker {kind}: 1: {one:.2f} s, 2: {two:.2f} s, "
          f"speed-up 2 workers / 1: {one / two:.2f}x")
    one, two = statistics.median(plain[1]), statistics.median(plain[2])
    print(f"plain processes median of {a.repeat}: 1 process {one:.2f} s, 2 processes {two:.2f} s, "
          f"speed-up {one / two:.2f}x")


if __name__ == "__main__":
    main()
