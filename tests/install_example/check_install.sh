#!/usr/bin/env bash
# Installs the build tree into a fresh prefix and builds tests/install_example against it, once
# with find_package(hpcontact) and once with pkg-config; both programs must give the energy that
# `hpcontact solve` of the installed executable prints for the same scene.
# With PYTHON_SITE (the Python package folder relative to the prefix), the installed Python module
# must import from there and give the same energy.
#   check_install.sh BUILD_DIR EXAMPLE_SOURCE_DIR [PYTHON_SITE]
set -euo pipefail
build=$1 source=$2 python_site=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > /dev/null

# 1. CMake package.
cmake -S "$source" -B "$work/example" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$work/example" > /dev/null
by_cmake=$("$work/example/solve_paper_scene" "$work/out_cmake")

# 2. pkg-config.
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig:${PKG_CONFIG_PATH:-}"
# shellcheck disable=SC2046
c++ -O1 "$source/solve_paper_scene.cpp" -o "$work/by_pkg_config" $(pkg-config --cflags --libs hpcontact)
by_pkg_config=$("$work/by_pkg_config" "$work/out_pkg_config")

# 3. The installed executable on the scene the example wrote.
by_cli=$("$work/prefix/bin/hpcontact" solve "$work/out_cmake/scene.toml" --effects friction_s --out "$work/out_cli" | grep '^friction_s:' | sed 's/, .*//')

echo "find_package: $by_cmake"
echo "pkg-config:   $by_pkg_config"
echo "hpcontact:    $by_cli"
[ "$by_cmake" = "$by_cli" ] && [ "$by_pkg_config" = "$by_cli" ] && [ -f "$work/out_cmake/summary.json" ] ||
  { echo "check_install: the programs disagree" >&2; exit 1; }

# 4. The Python module from the installed tree (not the build tree's).
if [ -n "$python_site" ]; then
  by_python=$(cd "$work" && PYTHONPATH="$work/prefix/$python_site" /usr/bin/python3 -c "
import sys, hpcontact
assert hpcontact.__file__.startswith(sys.argv[2]), hpcontact.__file__
print(repr(hpcontact.solve(sys.argv[1], effects=['friction_s']).summary['friction_s']['energy']))" \
    "$work/out_cmake/scene.toml" "$work/prefix")
  echo "python:       $by_python"
  /usr/bin/python3 -c "import sys; sys.exit(float(sys.argv[1]) != float(sys.argv[2]))" "$by_python" "${by_cli##*= }" ||
    { echo "check_install: the Python module disagrees" >&2; exit 1; }
fi
