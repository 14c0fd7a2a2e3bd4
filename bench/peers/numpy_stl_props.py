#!/usr/bin/env python3
"""Peer for bench/compare_peers.sh: numpy-stl (python3-stl) mass properties of an STL."""
import sys

from stl import mesh


def main(path):
    m = mesh.Mesh.from_file(path)
    volume, cog, inertia = m.get_mass_properties()
    print("volume %.17g cog %.17g %.17g %.17g" % (volume, cog[0], cog[1], cog[2]))


if __name__ == "__main__":
    main(sys.argv[1])
