#!/usr/bin/env python3
"""Peer for bench/compare_peers.sh: Open3D (python3-open3d) load + surface area."""
import sys

import open3d as o3d


def main(path):
    mesh = o3d.io.read_triangle_mesh(path)
    print("triangles %d area %.17g" % (len(mesh.triangles), mesh.get_surface_area()))


if __name__ == "__main__":
    main(sys.argv[1])
