"""Builds the Python module with the project's CMake build (setuptools only drives it).

Only the module's target is built (tests, benchmarks off) for the Python running pip, and its own
install rule stages it. CMAKE_ARGS adds configure options (e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache);
CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


def project_version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    return re.search(r"project\(tubemesh VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            sys.exit("tubemesh: cmake is not on PATH (tools/setup.sh installs it with the other build packages)")
        # Beside the presets' trees (build/release, ...): same depth, so ccache serves their objects.
        build = SOURCE / "build" / "pip"
        target = Path(self.get_ext_fullpath(ext.name)).resolve().parent
        configure = ["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DTUBEMESH_BUILD_TESTS=OFF", "-DTUBEMESH_BUILD_BENCH=OFF", "-DTUBEMESH_BUILD_PYTHON=ON",
                     f"-DPython_EXECUTABLE={sys.executable}", "-DTUBEMESH_INSTALL_PYTHONDIR=."]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "tubemesh_python", "-j", jobs], check=True)
        subprocess.run(["cmake", "--install", str(build), "--component", "python", "--prefix", str(target)],
                       check=True)


setup(version=project_version(), ext_modules=[CMakeExtension("tubemesh")], cmdclass={"build_ext": CMakeBuild})
