"""Builds the extension pgamesh._pgamesh with CMake for `pip install --no-build-isolation .`.

The CMake project is configured with only the Python module on (no tests, benchmarks or viewer),
for the interpreter running pip (Python_EXECUTABLE), and the target pgamesh_python is built; the
module it makes is copied where setuptools expects the extension. PGAMESH_BUILD_JOBS sets the
build's parallelism (default 2). docs/python.md, "Installing".
"""

import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    """build_ext that runs CMake instead of compiling sources itself."""

    def build_extension(self, ext: Extension) -> None:
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DCMAKE_UNITY_BUILD=ON", "-DPGAMESH_BUILD_PYTHON=ON",
                     "-DPGAMESH_BUILD_TESTS=OFF", "-DPGAMESH_BUILD_BENCH=OFF",
                     "-DPGAMESH_BUILD_VIEWER=OFF", f"-DPython_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        subprocess.run(configure, check=True)
        jobs = os.environ.get("PGAMESH_BUILD_JOBS", "2")
        subprocess.run(["cmake", "--build", str(build), "--target", "pgamesh_python", "-j", jobs],
                       check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build / "python" / "pgamesh" / ("_pgamesh" + suffix)
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(ext_modules=[Extension("pgamesh._pgamesh", sources=[])], cmdclass={"build_ext": CMakeBuild})
