"""Builds the extension freestand._freestand with the project's own CMake build (the parent
folder's CMakeLists.txt, target freestand_python) and puts it into the wheel beside the package
python/freestand/. Run by `pip install --no-build-isolation ./python` (README "Python").

FREESTAND_BUILD_BASE, when set, is the folder setuptools builds in (its build/ and egg-info),
so that a build leaves nothing in the source tree; by default it is python/build/ (ignored by
git), where a second install reuses the CMake build.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

PYTHON_DIR = Path(__file__).resolve().parent
PROJECT_DIR = PYTHON_DIR.parent
BUILD_BASE = Path(os.environ.get("FREESTAND_BUILD_BASE") or PYTHON_DIR / "build").resolve()


def project_version() -> str:
    """The version of CMakeLists.txt's `project(freestand VERSION x.y.z ...)`."""
    text = (PROJECT_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    found = re.search(r"project\(\s*freestand\s+VERSION\s+([0-9][0-9.]*)", text)
    if not found:
        raise RuntimeError(f"no project(freestand VERSION ...) in {PROJECT_DIR / 'CMakeLists.txt'}")
    return found.group(1)


def compiler_cache_env() -> dict:
    """The presets' compiler-cache settings (CMakePresets.json): objects compile the same from any
    clone and build folder, so an install reuses what other builds compiled."""
    env = dict(os.environ)
    env.setdefault("CCACHE_BASEDIR", str(PROJECT_DIR))
    env.setdefault("CCACHE_NOHASHDIR", "1")
    env.setdefault("CCACHE_SLOPPINESS", "pch_defines,time_macros,include_file_mtime,include_file_ctime")
    return env


class CMakeBuild(build_ext):
    """Configures the project with only the Python module on, builds freestand_python and copies
    the _freestand shared object where setuptools packs the extension."""

    def build_extension(self, ext: Extension) -> None:
        cmake_dir = Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(PROJECT_DIR), "-B", str(cmake_dir),
                     "-DCMAKE_BUILD_TYPE=Release", "-DFREESTAND_TESTS=OFF", "-DFREESTAND_BENCH=OFF",
                     "-DFREESTAND_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja") and not (cmake_dir / "CMakeCache.txt").exists():
            configure += ["-G", "Ninja"]
        build = ["cmake", "--build", str(cmake_dir), "--target", "freestand_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(os.cpu_count() or 1)]
        env = compiler_cache_env()
        subprocess.run(configure, check=True, env=env)
        subprocess.run(build, check=True, env=env)

        built = sorted((cmake_dir / "python" / "freestand").glob("_freestand*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one _freestand*.so in {cmake_dir / 'python' / 'freestand'}, "
                               f"found {[p.name for p in built]}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(built[0], target)


BUILD_BASE.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    ext_modules=[Extension("freestand._freestand", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(BUILD_BASE)}, "egg_info": {"egg_base": str(BUILD_BASE)}},
)
