"""Builds the extension freestand._freestand with the project's own CMake build (the parent
folder's CMakeLists.txt, target freestand_python) and puts it into the wheel beside the package
python/freestand/. Run by `pip install --no-build-isolation ./python` (README "Python").

Environment:
  FREESTAND_CMAKE_BUILD_DIR  the CMake build folder; a relative path is taken from the project
                             folder. By default build/pip, which git ignores and where a second
                             install reuses the build. Setuptools' own build files and egg-info
                             go in its setuptools/ subfolder, so python/ gains nothing.
  FREESTAND_CMAKE_ARGS       more arguments for the CMake configure step (shell-quoted, after this
                             file's own, so they override them), e.g. "-DFREESTAND_WERROR=ON".

The compiler cache reuses another build's objects only when the compile command is the same once
CCACHE_BASEDIR (the project folder) is taken out of it: the same options that change compile flags
(FREESTAND_WERROR, the build type, FREESTAND_PYTHON's position-independent code) and a build folder
at the same depth below the project, as build/pip is beside the presets' build/<preset>.
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

PYTHON_DIR = Path(__file__).resolve().parent
PROJECT_DIR = PYTHON_DIR.parent
CMAKE_BUILD_DIR = (PROJECT_DIR / (os.environ.get("FREESTAND_CMAKE_BUILD_DIR") or "build/pip")).resolve()
SETUPTOOLS_DIR = CMAKE_BUILD_DIR / "setuptools"


def project_version() -> str:
    """The version of CMakeLists.txt's `project(freestand VERSION x.y.z ...)`."""
    text = (PROJECT_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    found = re.search(r"project\(\s*freestand\s+VERSION\s+([0-9][0-9.]*)", text)
    if not found:
        raise RuntimeError(f"no project(freestand VERSION ...) in {PROJECT_DIR / 'CMakeLists.txt'}")
    return found.group(1)


def compiler_cache_env() -> dict:
    """The presets' compiler-cache settings (CMakePresets.json): objects compile the same from any
    clone and build folder of the same depth, so an install reuses what other builds compiled."""
    env = dict(os.environ)
    env.setdefault("CCACHE_BASEDIR", str(PROJECT_DIR))
    env.setdefault("CCACHE_NOHASHDIR", "1")
    env.setdefault("CCACHE_SLOPPINESS", "pch_defines,time_macros,include_file_mtime,include_file_ctime")
    return env


class CMakeBuild(build_ext):
    """Configures the project with only the Python module on, builds freestand_python and copies
    the _freestand shared object where setuptools packs the extension."""

    def build_extension(self, ext: Extension) -> None:
        configure = ["cmake", "-S", str(PROJECT_DIR), "-B", str(CMAKE_BUILD_DIR),
                     "-DCMAKE_BUILD_TYPE=Release", "-DFREESTAND_TESTS=OFF", "-DFREESTAND_BENCH=OFF",
                     "-DFREESTAND_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"]
        # The presets' generator: with Make the compiler runs in each target's folder, a depth
        # the compiler cache would not match.
        if shutil.which("ninja") and not (CMAKE_BUILD_DIR / "CMakeCache.txt").exists():
            configure += ["-G", "Ninja"]
        configure += shlex.split(os.environ.get("FREESTAND_CMAKE_ARGS", ""))
        build = ["cmake", "--build", str(CMAKE_BUILD_DIR), "--target", "freestand_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(os.cpu_count() or 1)]
        env = compiler_cache_env()
        subprocess.run(configure, check=True, env=env)
        subprocess.run(build, check=True, env=env)

        package_dir = CMAKE_BUILD_DIR / "python" / "freestand"
        built = sorted(package_dir.glob("_freestand*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one _freestand*.so in {package_dir}, "
                               f"found {[p.name for p in built]}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(built[0], target)


SETUPTOOLS_DIR.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    ext_modules=[Extension("freestand._freestand", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(SETUPTOOLS_DIR)}, "egg_info": {"egg_base": str(SETUPTOOLS_DIR)}},
)
