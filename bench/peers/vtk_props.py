#!/usr/bin/env python3
"""Peer for bench/compare_peers.sh: VTK's vtkMassProperties (python3-vtk9) on STL, OBJ or PLY."""
import sys

import vtk


def main(path):
    lower = path.lower()
    if lower.endswith(".stl"):
        reader = vtk.vtkSTLReader()
    elif lower.endswith(".obj"):
        reader = vtk.vtkOBJReader()
    elif lower.endswith(".ply"):
        reader = vtk.vtkPLYReader()
    else:
        sys.exit("vtk_props: unsupported format " + path)
    reader.SetFileName(path)
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(reader.GetOutputPort())
    props = vtk.vtkMassProperties()
    props.SetInputConnection(triangles.GetOutputPort())
    props.Update()
    print("volume %.17g area %.17g" % (props.GetVolume(), props.GetSurfaceArea()))


if __name__ == "__main__":
    main(sys.argv[1])
