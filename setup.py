"""`pip install .` of the caskdem Python module: its native part built by this project's CMake
(the Release build, the module's target only) and installed with the package's Python files.
Run with Debian's setuptools and wheel, offline: `pip install --no-build-isolation .`
(docs/python.md, "Getting it")."""

import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = re.search(r"project\(caskdem VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, extension):
        target = pathlib.Path(self.get_ext_fullpath(extension.name)).resolve()
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                        "-DCASKDEM_BUILD_TESTS=OFF", "-DCASKDEM_BUILD_BENCHMARKS=OFF", "-DCASKDEM_WITH_PYTHON=ON",
                        f"-DCASKDEM_PYTHON={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "_caskdem", "-j", str(os.cpu_count() or 1)],
                       check=True)
        built = next((build / "python" / "caskdem").glob("_caskdem*.so"))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    name="caskdem",
    version=VERSION,
    description="Seismic response of free-standing casks: rocking, sliding and tip-over, one run or thousands",
    packages=["caskdem"],
    package_dir={"caskdem": "src/python/caskdem"},
    ext_modules=[CMakeExtension("caskdem._caskdem")],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.11",
    install_requires=["numpy"],  # h5py too for read_result; Debian's python3-numpy and python3-h5py
    zip_safe=False,
    options={"build": {"build_base": "build/pip"}},  # beside the CMake build, not in it
)
