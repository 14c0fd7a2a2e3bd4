#!/usr/bin/env python3
"""Writes the test meshes of orientation by nesting (docs/conventions.md §8) as OBJ into DIR:
nested cubes (sides 8, 4, 2), a hollow cube (8 with a cavity of 1), two separate solids and a
torus (R 4, r 2) with a toroidal cavity (R 4, r 1), each right and with shells turned the wrong
way; faces as triangles. Usage: orientation_meshes.py DIR"""
import os
import sys

import bench_meshes

CUBE_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (1, 2, 6, 5), (0, 4, 7, 3)]


def cube(side, centre, outward):
    h = side / 2
    cx, cy, cz = centre
    v = [(cx + x, cy + y, cz + z) for z in (-h, h) for (x, y) in ((-h, -h), (h, -h), (h, h), (-h, h))]
    f = CUBE_FACES if outward else [tuple(reversed(q)) for q in CUBE_FACES]
    return v, f


def torus(major, minor, around, across, outward):
    return bench_meshes.torus(major, minor, around, across, outward=outward)


def write(path, shells):
    with open(path, "w") as out:
        base = 1
        for v, f in shells:
            for p in v:
                out.write("v %r %r %r\n" % p)
            for q in f:  # as fans of triangles: CGAL's PMP::volume takes triangles only
                for k in range(2, len(q)):
                    out.write("f %d %d %d\n" % (q[0] + base, q[k - 1] + base, q[k] + base))
            base += len(v)


def main():
    d = sys.argv[1]
    os.makedirs(d, exist_ok=True)
    for wrong in range(8):
        write(os.path.join(d, "nested_cubes_wrong%d.obj" % wrong),
              [cube(8, (0, 0, 0), not wrong & 1), cube(4, (0, 0, 0), bool(wrong & 2)),
               cube(2, (0, 0, 0), not wrong & 4)])
    write(os.path.join(d, "hollow_cube_right.obj"), [cube(2, (0, 0, 0), True), cube(1, (0.25, -0.125, 0.25), False)])
    write(os.path.join(d, "hollow_cube_wrong.obj"), [cube(2, (0, 0, 0), True), cube(1, (0.25, -0.125, 0.25), True)])
    write(os.path.join(d, "two_solids_wrong.obj"), [cube(2, (0, 0, 0), True), cube(1, (5, 0, 0), False)])
    for wrong in range(4):
        write(os.path.join(d, "torus_cavity_wrong%d.obj" % wrong),
              [torus(4, 2, 48, 24, not wrong & 1), torus(4, 1, 48, 24, bool(wrong & 2))])


main()
