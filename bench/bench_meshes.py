"""Meshes that the comparison scripts share, as (vertices, faces) with faces as tuples of vertex
indices: a torus of quads and the fans that triangulate polygons."""
import math


def torus(major, minor, around, across, centre=(0.0, 0.0, 0.0), outward=True):
    """The torus about the z axis through `centre`: tube radius `minor` about the circle of radius
    `major`, around x across quads, facing out (or in)."""
    v = []
    for i in range(around):
        u = 2 * math.pi * i / around
        for j in range(across):
            w = 2 * math.pi * j / across
            rho = major + minor * math.cos(w)
            v.append((centre[0] + rho * math.cos(u), centre[1] + rho * math.sin(u),
                      centre[2] + minor * math.sin(w)))
    at = lambda i, j: (i % around) * across + (j % across)
    f = [(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1))
         for i in range(around) for j in range(across)]
    if not outward:
        f = [tuple(reversed(q)) for q in f]
    return v, f


def fans(faces):
    """Each polygon (c0, c1, ..., cn) as its fan of triangles (c0, ck-1, ck)."""
    return [(q[0], q[k - 1], q[k]) for q in faces for k in range(2, len(q))]
