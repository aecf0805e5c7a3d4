"""`pip install .`: the module magnus built by the project's own CMake.

build_ext configures CMake in the setuptools build tree (Release, MAGNUS_PYTHON=ON, no tests, for the
interpreter doing the build), builds only the target magnus_python and copies _magnus*.so into the
package; build_py copies every python/magnus/*.py. The version is CMake's project version. ccache is used
when it is on PATH. Extra CMake arguments: MAGNUS_CMAKE_ARGS; parallel jobs: CMAKE_BUILD_PARALLEL_LEVEL.
A failed step stops with one line naming what is missing; the full CMake output is kept in a log.
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

HERE = Path(__file__).resolve().parent
MISSING_HINT = "scripts/setup.sh installs every Debian package magnus needs"


def project_version():
    """The x.y.z of `project(magnus VERSION x.y.z …)` in CMakeLists.txt, the project's one version."""
    if not (HERE / "CMakeLists.txt").is_file():
        sys.exit(f"magnus: no CMakeLists.txt in {HERE} (an sdist has no C++ sources): build the wheel from "
                 "the source tree, with pip install . or python3 -m build --wheel")
    text = (HERE / "CMakeLists.txt").read_text(encoding="utf-8")
    m = re.search(r"^project\(\s*magnus\s+VERSION\s+([0-9][0-9.]*)", text, re.MULTILINE)
    if not m:
        sys.exit("magnus: no `project(magnus VERSION …)` line in CMakeLists.txt")
    return m.group(1)


def base_python():
    """The interpreter the module is built for: a venv's base (/usr/bin/python3 for a Debian venv), whose
    headers and ABI the venv shares, else the running one."""
    return getattr(sys, "_base_executable", None) or sys.executable


def first_cmake_error(log):
    """CMake's first error message as one line (its indented paragraphs joined), or None."""
    lines = log.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("CMake Error"):
            body = []
            for text in lines[i + 1:]:
                if text and not text.startswith(" "):
                    break
                body.append(text.strip())
            return " ".join((" ".join(body) or line.split(":", 1)[-1]).split())
    return None


# What CMake or pkg-config calls a dependency → the Debian package that provides it.
DEBIAN_PACKAGES = {
    "Eigen3": "libeigen3-dev", "HDF5": "libhdf5-dev", "CLI11": "libcli11-dev", "fmt": "libfmt-dev",
    "nlohmann_json": "nlohmann-json3-dev", "PkgConfig": "pkg-config", "tomlplusplus": "libtomlplusplus-dev",
    "fftw3": "libfftw3-dev", "plplot-c++": "libplplot-dev", "pybind11": "pybind11-dev python3-dev",
}


def missing_package(log):
    """The first dependency CMake or pkg-config did not find, or None."""
    m = re.search(r'provided by "([^"]+)"|Could NOT find (\S+)|No package \'([^\']+)\' found|'
                  r"Package '([^']+)', required by '[^']*', not found", log)
    return next(name for name in m.groups() if name) if m else None


def missing_line(log):
    """What a failed configure lacks, as one line naming the Debian packages where we know them."""
    error = (first_cmake_error(log) or "CMake failed").split(" It fails with the following output:")[0]
    error = error if len(error) <= 300 else error[:300] + "…"
    if re.search(r"compiler|build program", error, re.IGNORECASE):
        return "no working C/C++ compiler or make (apt-get install build-essential, or set CC and CXX): " + error
    if "apt-get" in error:
        return error
    name = missing_package(log)
    if name:
        package = DEBIAN_PACKAGES.get(name)
        return f"{name} not found ({'apt-get install ' + package + '; ' if package else ''}{MISSING_HINT})"
    return f"{error} ({MISSING_HINT})"


def run_logged(cmd, log_path, what):
    """Run cmd with its output in log_path; on failure stop with what(output) as the one line."""
    with open(log_path, "w", encoding="utf-8") as log:
        rc = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, check=False).returncode
    if rc != 0:
        text = Path(log_path).read_text(encoding="utf-8", errors="replace")
        raise SystemExit(f"magnus: {what(text)} [full output: {log_path}]")


def first_compile_error(log):
    """The build's first `error:` line, for the one-line report of a failed build."""
    for line in log.splitlines():
        if "error:" in line or "Error " in line:
            return "building the module failed: " + " ".join(line.split())
    return "building the module failed"


class CMakeExtension(Extension):
    """The pybind11 module, built by CMake's target `target` (no sources of its own for setuptools)."""

    def __init__(self, name, target):
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    """Configure and build the CMake project in the setuptools build tree, then copy the module."""

    def cmake_arguments(self, python):
        args = ["-DCMAKE_BUILD_TYPE=Release", "-DMAGNUS_PYTHON=ON", "-DMAGNUS_TESTS=OFF",
                f"-DPython_EXECUTABLE={python}"]
        if shutil.which("ccache"):
            args += ["-DCMAKE_C_COMPILER_LAUNCHER=ccache", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
        return args + shlex.split(os.environ.get("MAGNUS_CMAKE_ARGS", ""))

    def build_extension(self, ext):
        if not shutil.which("cmake"):
            raise SystemExit("magnus: cmake not found (apt-get install cmake build-essential; " + MISSING_HINT + ")")
        build = Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        python = base_python()
        configure = ["cmake", "-S", str(HERE), "-B", str(build)] + self.cmake_arguments(python)
        try:
            run_logged(configure, build / "configure.log", missing_line)
        except SystemExit:  # the next try starts afresh: no cached NOTFOUND, no cached compiler
            (build / "CMakeCache.txt").unlink(missing_ok=True)
            for detected in (build / "CMakeFiles").glob("[0-9]*"):
                shutil.rmtree(detected, ignore_errors=True)
            raise
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        run_logged(["cmake", "--build", str(build), "--target", ext.target, "-j", jobs], build / "build.log",
                   first_compile_error)
        built = sorted((build / "python" / "magnus").glob("_magnus*.so"))
        if len(built) != 1:
            raise SystemExit(f"magnus: expected one _magnus*.so in {build / 'python' / 'magnus'}, found {len(built)}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


(HERE / "build" / "pip").mkdir(parents=True, exist_ok=True)  # egg_base must exist before egg_info runs
setup(
    version=project_version(),
    packages=["magnus"],
    package_dir={"magnus": "python/magnus"},
    ext_modules=[CMakeExtension("magnus._magnus", target="magnus_python")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build/pip"}, "egg_info": {"egg_base": "build/pip"}},
    zip_safe=False,
)
