"""Typed stubs of the extension module pgamesh._pgamesh (docs/python.md)."""

import os
import types
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

#: pgamesh.pga3 (PGA R(3,0,1)) and pgamesh.models (CGA objects, quadrics): see their docstrings.
pga3: types.ModuleType
models: types.ModuleType

_Vec3 = Union[Sequence[float], npt.NDArray[np.float64]]

class InputError(ValueError):
    """A file (or bytes) that cannot be read as a mesh, with the position of the problem."""
    file: str
    line: Optional[int]
    column: Optional[int]
    byte_offset: Optional[int]

class Mesh:
    """A polygon mesh: vertices and faces as numpy arrays; figures computed on first use."""
    def __init__(self, vertices: npt.ArrayLike, faces: Union[npt.ArrayLike, Sequence[Sequence[int]]],
                 weld_tolerance: Optional[float] = None) -> None: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """(n, 3) read-only view of the vertices (no copy)."""
    @property
    def faces(self) -> Union[npt.NDArray[np.uint32], List[npt.NDArray[np.uint32]]]:
        """(m, 3) uint32 view for triangles; a list of arrays for other polygons."""
    @property
    def corners(self) -> npt.NDArray[np.uint32]:
        """Every face's vertex indices, face after face (view)."""
    @property
    def face_offsets(self) -> npt.NDArray[np.uint32]:
        """Face f is corners[face_offsets[f]:face_offsets[f + 1]] (view)."""
    @property
    def format(self) -> str:
        """The format read ('stl-binary', …; 'unknown' for arrays)."""
    @property
    def weld_tolerance(self) -> float:
        """The weld tolerance of the topology."""
    @property
    def triangles(self) -> int:
        """Triangles of the faces' fans."""
    @property
    def area(self) -> float:
        """Surface area."""
    @property
    def volume(self) -> float:
        """Signed volume."""
    @property
    def center_mass(self) -> npt.NDArray[np.float64]:
        """Centre of mass (NaN when the volume is 0)."""
    @property
    def moment_inertia(self) -> npt.NDArray[np.float64]:
        """3×3 inertia tensor about the centre of mass, density 1, I_xy = -∫xy dm."""
    @property
    def principal_inertia_components(self) -> npt.NDArray[np.float64]:
        """Principal moments, ascending."""
    @property
    def principal_inertia_vectors(self) -> npt.NDArray[np.float64]:
        """Principal axes as rows."""
    @property
    def principal_motor(self) -> Any:
        """The motor placing the principal frame."""
    @property
    def gap_area(self) -> float:
        """½‖Σ F‖: 0 for a closed surface."""
    @property
    def is_watertight(self) -> bool:
        """Every edge shared by exactly two faces."""
    @property
    def is_winding_consistent(self) -> bool:
        """No edge used twice in one direction."""
    @property
    def is_volume(self) -> bool:
        """Volume, centre of mass and inertia describe a solid."""
    @property
    def reasons(self) -> List[str]:
        """Why the volume is not valid."""
    @property
    def warnings(self) -> List[str]:
        """Reader repairs, float32 precision."""
    @property
    def boundary_loops(self) -> List[Dict[str, Any]]:
        """Boundary loops: vertices, corners, closed, vector_area, area, perimeter."""
    def mass_properties(self, *, density: Optional[float] = None,
                        mass: Optional[float] = None) -> Dict[str, Any]:
        """trimesh's mass_properties dict and more."""
    def props(self) -> Dict[str, Any]:
        """The document of `pgamesh props --json` for this mesh."""
    def check(self) -> Dict[str, Any]:
        """The document of `pgamesh check --json` for this mesh."""

def load(source: Union[str, os.PathLike, bytes, bytearray, memoryview],
         weld_tolerance: Optional[float] = None, format: Optional[str] = None) -> Mesh:
    """Reads a mesh (STL, OBJ, PLY, OFF) from a path or bytes."""

def analyze_file(path: Union[str, os.PathLike], *, density: Optional[float] = None,
                 mass: Optional[float] = None,
                 weld_tolerance: Optional[float] = None, topology: bool = True,
                 format: Optional[str] = None, threads: int = 0) -> Dict[str, Any]:
    """The document of `pgamesh props --json FILE`."""

class Tank:
    """A closed mesh prepared for fuel queries."""
    def __init__(self, mesh: Mesh, *, force: bool = False) -> None: ...
    @property
    def volume(self) -> float: ...
    @property
    def problems(self) -> List[str]: ...
    def fuel(self, up: _Vec3, *, level: Optional[float] = None, volume: Optional[float] = None,
             fraction: Optional[float] = None) -> Dict[str, Any]:
        """The dict of `pgamesh fuel --json` at one level."""
    def level_for_volume(self, up: _Vec3, volume: float) -> float:
        """The level holding `volume`."""
    def table(self, up: _Vec3, n: int) -> Dict[str, npt.NDArray[np.float64]]:
        """A gauge table of n + 1 levels as arrays."""
    def attitudes(self, pitch_deg: Sequence[float], roll_deg: Sequence[float], *,
                  volume: Optional[float] = None, fraction: Optional[float] = None,
                  up: _Vec3 = (0.0, 0.0, 1.0)) -> Dict[str, npt.NDArray[np.float64]]:
        """The fuel of one volume over a pitch × roll grid."""
