#!/usr/bin/env python3
"""Field by field, the JSON two builds of pgamesh print for the same meshes.

    bench/compare_builds.py OLD_PGAMESH NEW_PGAMESH [--root DIR ...] -- props --json

Runs `PGAMESH COMMAND... FILE` with both programs for every mesh file under the roots (default:
data/meshes, tests/data/meshes, and ../shared/meshes and ../shared/golden when present) and lists
the files whose output differs, with each differing field: its relative change for numbers, the
old and new values otherwise. A change of the printed figures shows up here, bit for bit.
"""
import argparse
import json
import os
import subprocess
import sys

EXTENSIONS = ('.stl', '.obj', '.ply', '.off', '.3mf', '.glb', '.gltf', '.slp')


def mesh_files(roots):
    for root in roots:
        for folder, _, names in os.walk(root):
            for name in sorted(names):
                if name.lower().endswith(EXTENSIONS):
                    yield os.path.join(folder, name)


def run(program, command, path):
    r = subprocess.run([program] + command + [path], capture_output=True, text=True, timeout=600)
    try:
        return r.returncode, json.loads(r.stdout)
    except ValueError:
        return r.returncode, r.stdout


def fields(value, prefix=''):
    if isinstance(value, dict):
        for k, v in value.items():
            yield from fields(v, prefix + '.' + k)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from fields(v, f'{prefix}[{i}]')
    else:
        yield prefix, value


def changes(old, new):
    a, b = dict(fields(old)), dict(fields(new))
    for key in sorted(set(a) | set(b)):
        x, y = a.get(key), b.get(key)
        if x == y:
            continue
        if isinstance(x, float) and isinstance(y, float) and x != 0:
            yield f'{key} rel {abs(y - x) / abs(x):.2g}'
        else:
            yield f'{key}: {str(x)[:60]!r} -> {str(y)[:60]!r}'


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    repo = os.path.dirname(here)
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('old')
    p.add_argument('new')
    p.add_argument('--root', action='append', help='folder of meshes (repeatable)')
    p.add_argument('command', nargs=argparse.REMAINDER, help='-- and the pgamesh command')
    a = p.parse_args()
    command = a.command[1:] if a.command[:1] == ['--'] else a.command
    if not command:
        p.error('give the command after --, e.g. -- props --json')
    roots = a.root or [os.path.join(repo, 'data/meshes'), os.path.join(repo, 'tests/data/meshes')] + [
        d for d in (os.path.join(repo, '../shared/meshes'), os.path.join(repo, '../shared/golden'))
        if os.path.isdir(d)]
    files = list(mesh_files(roots))
    differing = []
    for path in files:
        (old_status, old), (new_status, new) = run(a.old, command, path), run(a.new, command, path)
        if (old_status, old) == (new_status, new):
            continue
        found = list(changes(old, new)) if isinstance(old, dict) and isinstance(new, dict) else [
            'output']
        if old_status != new_status:
            found.insert(0, f'exit status {old_status} -> {new_status}')
        differing.append((path, found))
    print(f'{len(files)} files, {len(files) - len(differing)} identical, {len(differing)} differ')
    for path, found in differing:
        more = f' (+{len(found) - 6} more)' if len(found) > 6 else ''
        print(f'{os.path.relpath(path, repo)}: ' + '; '.join(found[:6]) + more)
    return 0


if __name__ == '__main__':
    sys.exit(main())
