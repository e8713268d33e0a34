"""Builds the Python module with CMake for pip (pyproject.toml): configures a build with
only what the module needs (the library, the evaluation's metrics; no tool, tests, renderer),
builds the ssfx_python target and packages build/python/ssfx (module, wrappers, stubs)."""
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.join(ROOT, "build", "pip")
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DSSFX_BUILD_TESTS=OFF",
                        "-DSSFX_BUILD_BENCH=OFF", "-DSSFX_BUILD_APPS=OFF", "-DSSFX_BUILD_RENDER=OFF",
                        f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", build, "--target", "ssfx_python", "-j", str(os.cpu_count() or 2)],
                       check=True)
        dest = os.path.join(os.path.abspath(self.build_lib), "ssfx")
        shutil.copytree(os.path.join(build, "python", "ssfx"), dest, dirs_exist_ok=True)


setup(packages=[], ext_modules=[Extension("ssfx._ssfx", sources=[])], cmdclass={"build_ext": CMakeBuild})
