#!/usr/bin/env bash
# The package as pip installs it: into a fresh virtual environment of Debian's
# Python (with its site packages: numpy, pytest; --no-index: nothing
# downloaded), building the extension in the test build's CMake folder. Then
# pip knows it (list, version metadata), mypy sees its types (the typed
# example passes --strict and runs, a wrong keyword type is flagged), the module's tests pass
# against the installed package, pip uninstall removes it; and the README's
# CMake route (cmake --install --component python) gives an importable package.
#   usage: test_pip_install.sh SOURCE_DIR BUILD_DIR WORK_DIR PROGRAM SHARED_MESH_DIR
set -euo pipefail
source=$1 build=$2 work=$3 program=$4 shared=$5
for tool in /usr/bin/python3 mypy; do
  command -v "$tool" > /dev/null || { echo "SKIPPED: $tool missing (tools/install_dependencies.sh tests)"; exit 77; }
done
/usr/bin/python3 -c "import venv, ensurepip" 2> /dev/null || { echo "SKIPPED: python3-venv missing"; exit 77; }
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAILED: $*"; exit 1; }
unset PYTHONPATH

/usr/bin/python3 -m venv --system-site-packages venv
py="$work/venv/bin/python"
tree_before=$(git -C "$source" status --porcelain --ignored 2> /dev/null || true)
(cd "$source" && SMDF_CMAKE_BUILD_DIR="$build" "$py" -m pip install -v --no-build-isolation --no-index .) > pip.log 2>&1 \
  || { tail -20 pip.log; fail "pip install"; }
# pip writes nothing into the work tree (its builds live in the build folder or the user's cache)
[ "$(git -C "$source" status --porcelain --ignored 2> /dev/null || true)" = "$tree_before" ] \
  || fail "pip install left files in the work tree: $(git -C "$source" status --porcelain --ignored | head -5)"
# what the build said it was doing (pip -v shows it; a terminal sees it without -v)
grep -q "surface-mesh-direction-fields: building for $py" pip.log && grep -q "surface-mesh-direction-fields: extension built" pip.log \
  || fail "pip install -v does not show what the build does"
listed=$("$py" -m pip list 2> /dev/null)
grep -q "^surface-mesh-direction-fields " <<< "$listed" || fail "pip list does not show the package"
"$py" - "$work/venv" << 'PY' || fail "the installed package"
import importlib.metadata, os, sys
import surface_mesh_direction_fields as smdf
assert smdf.__file__.startswith(sys.argv[1]), smdf.__file__
assert importlib.metadata.version("surface-mesh-direction-fields") == smdf.__version__
folder = os.path.dirname(smdf.__file__)
assert os.path.exists(os.path.join(folder, "py.typed")) and os.path.exists(os.path.join(folder, "__init__.pyi"))
V = [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]]
r = smdf.compute_globally_optimal_directions(V, [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], degree=4)
assert r.index_sum == 8, r.index_sum  # n chi on a tetrahedron
PY
echo "installed: $("$py" -m pip show surface-mesh-direction-fields | grep -E '^(Name|Version|Location)' | tr '\n' ' ')"

example="$source/examples/Surface_mesh_direction_fields/python/cross_field.py"
mypy --python-executable "$py" --strict "$example" || fail "mypy --strict on the typed example"
printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n' > octahedron.off
ran=$("$py" "$example" octahedron.off octahedron.vtu) || fail "the typed example"
grep -Eq "^8 faces \(0 repairs\), [0-9]+ singular faces: .*, index sum 8/4$" <<< "$ran" \
  && [ -s octahedron.vtu ] || fail "the typed example's output: $ran"
printf 'import surface_mesh_direction_fields as smdf\nsmdf.compute_globally_optimal_directions([], [], degree="4")\n' > wrong_call.py
if mypy --python-executable "$py" wrong_call.py > mypy_wrong.txt; then fail "mypy accepted degree=\"4\""; fi
grep -q 'Argument "degree" to "compute_globally_optimal_directions" has incompatible type "str"' mypy_wrong.txt \
  || { cat mypy_wrong.txt; fail "mypy's message"; }

"$py" -m pytest -q -p no:cacheprovider "$source/python/tests" --direction-field "$program" --shared "$shared" \
  --installed-in "$work/venv" || exit $?

"$py" -m pip uninstall -y surface-mesh-direction-fields > /dev/null
if (cd / && "$py" -c "import surface_mesh_direction_fields" 2> /dev/null); then fail "still importable after pip uninstall"; fi

cmake --install "$build" --component python --prefix "$work/prefix" > /dev/null
site=$(find "$work/prefix" -type d -name surface_mesh_direction_fields)
PYTHONPATH=$(dirname "$site") /usr/bin/python3 -c "import surface_mesh_direction_fields as s; assert s.__file__.startswith('$work/prefix')" \
  || fail "cmake --install --component python"
echo "pip install, pip list, metadata, mypy, the module's tests, pip uninstall, cmake --install: all passed"
