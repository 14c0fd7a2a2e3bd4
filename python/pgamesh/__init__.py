"""pgamesh: geometric-algebra mesh processing from Python (docs/python.md).

The figures come from pgamesh's C++ library through the extension module ``pgamesh._pgamesh``;
this package re-exports it and adds the batch runner (``python3 -m pgamesh batch``).

>>> import pgamesh
>>> mesh = pgamesh.load("data/meshes/bunny.stl")
>>> mesh.volume, mesh.center_mass, mesh.moment_inertia       # trimesh's names
>>> pgamesh.analyze_file("data/meshes/bunny.stl")             # == `pgamesh props --json`

The inertia tensor follows trimesh's convention: positive diagonal, off-diagonal entries minus the
products of inertia (I_xy = -∫ x y dm), about the centre of mass.
"""

import sys as _sys

from ._pgamesh import InputError, Mesh, Tank, analyze_file, load, models, pga3

# The extension's submodules, importable by name: `from pgamesh.pga3 import point`.
_sys.modules[__name__ + ".pga3"] = pga3
_sys.modules[__name__ + ".models"] = models

__all__ = ["InputError", "Mesh", "Tank", "analyze_file", "load", "models", "pga3"]
__version__ = "0.1.0"
