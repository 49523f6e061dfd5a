"""Builds the extension vissort._vissort with the repository's CMake project (python/).

pip runs this through setuptools (pyproject.toml). It configures a build tree (by default
build-python/ at the repository root; VISSORT_CMAKE_BUILD_DIR picks another, e.g. an existing
build/ whose libraries are already compiled), builds the target vissort_python for the
interpreter running pip, and copies the module into the wheel. Needs cmake, a C++20 compiler
and Debian's pybind11-dev, python3-dev and python3-numpy (scripts/install-deps.sh).
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            sys.exit("vissort: cmake is needed to build the module (apt install cmake g++; "
                     "or bash scripts/install-deps.sh)")
        build_dir = Path(os.environ.get("VISSORT_CMAKE_BUILD_DIR", ROOT / "build-python"))
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                        "-DVISSORT_WITH_PYTHON=ON",
                        # The interpreter a virtual environment was made from: the same headers
                        # and ABI, and a build tree shared with the tests keeps its interpreter.
                        f"-DPython3_EXECUTABLE={getattr(sys, '_base_executable', sys.executable)}"]
                       + ([] if (build_dir / "CMakeCache.txt").exists() else
                          ["-DCMAKE_BUILD_TYPE=Release", "-DVISSORT_BUILD_TESTS=OFF"]),
                       check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "-j", jobs,
                        "--target", "vissort_python"], check=True)
        built = next((build_dir / "python" / "vissort").glob("_vissort*.so"))
        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, destination)


setup(ext_modules=[CMakeExtension("vissort._vissort")], cmdclass={"build_ext": CMakeBuild},
      # setuptools' own scratch space, out of CMake's build/ tree.
      options={"build": {"build_base": str(ROOT / "build-python" / "setuptools")}})
