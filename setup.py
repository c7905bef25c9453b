"""Builds the extension candela._candela with the project's own CMake build (pyproject.toml).

The extension is the CMake target candela_python (python/CMakeLists.txt), built for the
interpreter that runs pip, in the build folder CANDELA_BUILD_DIR (default build-pip/: build/
stays configured for scripts/build.sh's interpreter; ccache makes the library's compile mostly
hits), then copied where setuptools packs it.
"""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = pathlib.Path(os.environ.get("CANDELA_BUILD_DIR", ROOT / "build-pip"))
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                        "-DCANDELA_BUILD_TESTS=OFF",
                        f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "candela_python", "-j",
                        str(os.cpu_count() or 1)], check=True)
        built = build_dir / "python" / "candela" / pathlib.Path(self.get_ext_filename(ext.name)).name
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(ext_modules=[Extension("candela._candela", sources=[])], cmdclass={"build_ext": CMakeBuild})
