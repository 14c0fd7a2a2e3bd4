#!/usr/bin/env python3
"""Triangle meshes (OFF, vertices shared by index) for bench/compare_self_intersections.sh:
overlapping, touching and nested cubes, a folded cube, coplanar neighbours, crumpled spheres
(corners moved at random by more than the
edges are long, so that the surface folds) and two overlapping tori.
Usage: self_intersection_meshes.py OUTDIR"""
import math
import os
import random
import sys

import bench_meshes

CUBE_FACES = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
              (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]


def cube(offset, scale=1.0):
    v = [tuple(offset[k] + scale * ((i >> k) & 1) for k in range(3)) for i in range(8)]
    return v, list(CUBE_FACES)


def join(*meshes):
    vertices, faces = [], []
    for v, f in meshes:
        base = len(vertices)
        vertices += v
        faces += [tuple(base + i for i in t) for t in f]
    return vertices, faces


def sphere(radius, stacks, slices, wobble=0.0, seed=1):
    rng = random.Random(seed)
    v = [(0.0, 0.0, radius)]
    for i in range(1, stacks):
        theta = math.pi * i / stacks
        for j in range(slices):
            phi = 2 * math.pi * j / slices
            move = [wobble * radius * rng.uniform(-1, 1) for _ in range(3)]
            v.append((radius * math.sin(theta) * math.cos(phi) + move[0],
                      radius * math.sin(theta) * math.sin(phi) + move[1],
                      radius * math.cos(theta) + move[2]))
    v.append((0.0, 0.0, -radius))
    south = len(v) - 1
    f = []
    ring = lambda i, j: 1 + (i - 1) * slices + j % slices
    for j in range(slices):
        f.append((0, ring(1, j), ring(1, j + 1)))
        f.append((south, ring(stacks - 1, j + 1), ring(stacks - 1, j)))
    for i in range(1, stacks - 1):
        for j in range(slices):
            a, b, c, d = ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)
            f += [(a, b, c), (a, c, d)]
    return v, f


def torus(major, minor, around, across, centre):
    v, quads = bench_meshes.torus(major, minor, around, across, centre)
    return v, bench_meshes.fans(quads)


def write_off(path, mesh):
    v, f = mesh
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(v), len(f)))
        for p in v:
            out.write("%r %r %r\n" % p)
        for t in f:
            out.write("3 %d %d %d\n" % t)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    folded = cube((0, 0, 0))
    folded[0][7] = (0.25, 0.3, -0.5)
    coplanar = ([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0.25, 0.5, 0)], [(0, 1, 2), (1, 0, 3)])
    meshes = {
        "overlapping_cubes": join(cube((0, 0, 0)), cube((0.5, 0.5, 0.5))),
        "overlapping_cubes_offset": join(cube((0, 0, 0)), cube((0.3, 0.6, -0.2), 0.7)),
        "touching_face_welded": join(cube((0, 0, 0)), cube((1, 0, 0))),
        "touching_face_offset": join(cube((0, 0, 0)), cube((1, 0.25, 0.25), 0.5)),
        "touching_edge_welded": join(cube((0, 0, 0)), cube((1, 1, 0))),
        "touching_vertex_welded": join(cube((0, 0, 0)), cube((1, 1, 1))),
        "nested_cubes": join(cube((0, 0, 0), 3), cube((1, 1, 1))),
        "folded_cube": folded,
        "coplanar_neighbours": coplanar,
        "sphere": sphere(1, 24, 48),
        "crumpled_sphere": sphere(1, 24, 48, wobble=0.05, seed=7),
        "crumpled_sphere_fine": sphere(1, 100, 200, wobble=0.01, seed=11),
        "overlapping_tori": join(torus(3, 1, 64, 32, (0, 0, 0)), torus(3, 1, 64, 32, (2.5, 0.5, 0.3))),
    }
    for name, mesh in meshes.items():
        write_off(os.path.join(out, name + ".off"), mesh)


if __name__ == "__main__":
    main()
