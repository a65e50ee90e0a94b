"""setuptools' side of pyproject.toml: the package rtamp built by CMake.

build_ext configures CMake (if the build directory has no cache yet) with the
tests, benchmarks and web page off, builds the target rtamp_python and copies
the package CMake laid out (<build>/python/rtamp: the extension _rtamp, the .py
files, _rtamp.pyi, py.typed) into the wheel. The CMake build directory is
$RTAMP_CMAKE_BUILD_DIR, else build/pip in the source tree; pointing it at an
existing build tree reuses what is built there. The version is read from
CMakeLists.txt's project(rtamp VERSION ...), the one source of truth.
Invariant: nothing is fetched from the network (pip --no-build-isolation uses
Debian's setuptools and wheel).
"""

import os
import pathlib
import re
import shutil
import subprocess

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).resolve().parent


def cmake_version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    m = re.search(r"project\(rtamp\s+VERSION\s+([0-9.]+)", text)
    if not m:
        raise RuntimeError("CMakeLists.txt: no project(rtamp VERSION x.y.z)")
    return m.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("RTAMP_CMAKE_BUILD_DIR") or SOURCE / "build" / "pip").resolve()
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build), "-G", "Ninja",
                            "-DCMAKE_BUILD_TYPE=Release", "-DRTAMP_TESTS=OFF", "-DRTAMP_BENCH=OFF"],
                           check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(["cmake", "--build", str(build), "-j", jobs, "--target", "rtamp_python"], check=True)
        built = build / "python" / "rtamp"
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).parent
        target.mkdir(parents=True, exist_ok=True)
        for f in built.iterdir():
            if f.name.startswith("_rtamp") or f.name == "py.typed":
                shutil.copy2(f, target / f.name)


(SOURCE / "build").mkdir(exist_ok=True)  # egg_info's base (gitignored)
setup(
    version=cmake_version(),
    packages=["rtamp"],
    package_dir={"rtamp": "python/rtamp"},
    ext_modules=[Extension("rtamp._rtamp", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build/setuptools"}, "egg_info": {"egg_base": "build"}},
    zip_safe=False,
)
