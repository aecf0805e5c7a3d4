#!/usr/bin/env bash
# pip_install_test.sh SOURCE_DIR VERSION [PYTHON]: `pip install .` offline into a scratch venv (ctest -L pip).
# A copy of SOURCE_DIR (without .git and CMake build trees) is built both ways README.md gives:
#   PYTHON -m build --wheel --no-isolation, then VENV/bin/pip install --no-index the wheel;
#   VENV/bin/python -m pip install --no-index --no-build-isolation . (the same CMake tree, so cheap).
# After each, the installed magnus is imported from an unrelated directory with PYTHONPATH cleared: it
# must be the venv's, hold every python/magnus/*.py, report VERSION, and its lift (9-point stencil) must
# be Kutta–Joukowski's C_L = −2πα at α = 1 and 2. First, builds without pybind11, without a compiler and
# without toml++'s pkg-config file must each stop with one line naming the Debian package to install, and
# no traceback. Cleans up after itself.
set -euo pipefail
src="$(cd "$1" && pwd)"
version="$2"
python="${3:-/usr/bin/python3}"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/magnus-pip.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "pip_install_test: $*" >&2; exit 1; }

unset PYTHONPATH PYTHONHOME VIRTUAL_ENV
export PIP_CONFIG_FILE=/dev/null PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PYTHONDONTWRITEBYTECODE=1
# ccache (when setup.py finds it on PATH) sees paths relative to the scratch dir: a rerun hits the cache.
export CCACHE_BASEDIR="$tmp" CCACHE_NOHASHDIR=1

mkdir "$tmp/src" "$tmp/elsewhere"
tar -C "$src" --exclude=./.git --exclude=./dist --exclude-tag-all=CMakeCache.txt --exclude=./build/pip -cf - . |
  tar -C "$tmp/src" -xf -
"$python" -m venv --system-site-packages "$tmp/venv"
venv_python="$tmp/venv/bin/python"

# Bad input: one line naming what to install, a non-zero exit, no Python traceback.
expect_refusal() {  # expect_refusal PACKAGE ENV…: pip install under ENV fails naming PACKAGE
  local package="$1" out; shift
  if out="$(cd "$tmp/src" && env "$@" "$venv_python" -m pip install --no-index --no-build-isolation . 2>&1)"; then
    fail "pip install succeeded under $*"
  fi
  grep -q "Traceback" <<<"$out" && fail "a traceback under $*: $out"
  grep -q "^ *magnus: .*apt-get install .*$package" <<<"$out" || fail "no line naming $package under $*: $out"
}
expect_refusal pybind11-dev MAGNUS_CMAKE_ARGS=-DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON
expect_refusal build-essential CXX="$tmp/no-such-compiler"
expect_refusal libtomlplusplus-dev PKG_CONFIG_LIBDIR="$tmp/no-pkg-config-files"

# The installed module, from elsewhere: the venv's, complete, the project's version, the exact lift.
check_installed() {
  (cd "$tmp/elsewhere" && "$venv_python" - "$tmp/venv" "$version" "$tmp/src" <<'EOF'
import importlib.metadata, math, os, sys
import magnus
venv, version, src = sys.argv[1:4]
for f in (magnus.__file__, magnus._magnus.__file__):
    assert os.path.realpath(f).startswith(os.path.realpath(venv) + os.sep), f"{f} is not inside {venv}"
shipped = {n for n in os.listdir(os.path.join(src, "python", "magnus")) if n.endswith(".py")}
installed = set(os.listdir(os.path.dirname(magnus.__file__)))
assert shipped <= installed, f"not installed: {sorted(shipped - installed)}"
assert magnus.__version__ == version == importlib.metadata.version("magnus"), (magnus.__version__, version)
case = os.path.join(src, "cases", "spin_ratio_1.toml")
for alpha in (1.0, 2.0):
    r = magnus.run(case, solver__stencil="9-point", cylinder__spin_ratio=alpha)
    assert r.parameters["spin_ratio"] == alpha
    cl = r.forces["cl"]
    assert abs(cl + 2 * math.pi * alpha) < 1e-9, (alpha, cl)  # Kutta–Joukowski: C_L = −2πα
    print(f"alpha {alpha}: cl {cl!r}")
assert os.listdir(".") == [], "magnus.run wrote files without being asked"
print(magnus._magnus.__file__)
EOF
  ) || fail "the installed module failed the checks above"
}

# 1. python3 -m build --wheel --no-isolation, then the wheel into the venv.
(cd "$tmp/src" && "$python" -m build --wheel --no-isolation >"$tmp/build.log" 2>&1) ||
  { tail -20 "$tmp/build.log" >&2; fail "python3 -m build --wheel --no-isolation failed"; }
wheels=("$tmp"/src/dist/magnus-"$version"-*.whl)
[ -f "${wheels[0]}" ] || fail "no wheel magnus-$version-*.whl in dist/"
"$venv_python" -m pip install --no-index "${wheels[0]}" >/dev/null || fail "pip install of ${wheels[0]##*/} failed"
check_installed
"$venv_python" -m pip uninstall -y magnus >/dev/null

# 2. pip install . with the venv's own pip (no build isolation: the build tools are Debian's).
(cd "$tmp/src" && "$venv_python" -m pip install --no-index --no-build-isolation . >"$tmp/pip.log" 2>&1) ||
  { tail -20 "$tmp/pip.log" >&2; fail "pip install --no-index --no-build-isolation . failed"; }
check_installed
echo "pip_install_test: both ways installed a working magnus $version (${wheels[0]##*/})"
