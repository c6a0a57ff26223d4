#!/usr/bin/env bash
# Builds MoorDyn's Python wheel from source into a fresh virtual environment, the way MoorDyn's own
# wheel workflow does it (.github/workflows/python-wheels*.yml of MoorDyn): the C++ library with CMake
# (Release) into install/, then the wrapper's setup.py (wrappers/python/wheels.github/) linked to it.
#
# Usage: build_moordyn.sh VENV MOORDYN_GIT [TAG]
#   VENV         directory of the virtual environment to create (removed first if it exists)
#   MOORDYN_GIT  a git repository of MoorDyn (a clone or a bare mirror) that has the tag TAG
#   TAG          the pinned version, default v2.7.1
#
# Why not `pip wheel --no-binary moordyn moordyn==2.7.x`: the sdist on PyPI holds only the wrapper and
# the headers, not the library's .cpp files; its setup.py links against a libmoordyn prebuilt in
# install/, which the sdist cannot build.
#
# Needs: python3 (venv), a C++17 compiler, git; CMake comes from PyPI into the venv.
set -euo pipefail

venv=${1:?usage: build_moordyn.sh VENV MOORDYN_GIT [TAG]}
src_git=${2:?usage: build_moordyn.sh VENV MOORDYN_GIT [TAG]}
tag=${3:-v2.7.1}
jobs=${JOBS:-2}

rm -rf "$venv"
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --upgrade pip
"$venv/bin/pip" install --quiet cmake numpy setuptools cython wheel

src="$venv/moordyn-src"
mkdir -p "$src"
# Only what the library and the wrapper need. A mirror without the large test data makes git print
# "error: invalid object ... tests/..." here and carry on: those files are not extracted or needed.
git -C "$src_git" archive "$tag" CMakeLists.txt cmake source wrappers README.md LICENSE.txt | tar -x -C "$src"
cd "$src"
# The wheel workflow's recipe: the wheel's setup.py, version and Eigen data at the root.
cp wrappers/python/wheels.github/* ./
"$venv/bin/python" set_version.py
"$venv/bin/python" set_eigen_data.py

start=$(date +%s.%N)
"$venv/bin/cmake" -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=install \
    -DEXTERNAL_EIGEN:BOOL=OFF -DPYTHON_WRAPPER:BOOL=OFF -DFORTRAN_WRAPPER:BOOL=OFF \
    -DRUST_WRAPPER:BOOL=OFF -DBUILD_TESTING=OFF >cmake-configure.log
"$venv/bin/cmake" --build build --config Release -j "$jobs" >cmake-build.log
"$venv/bin/cmake" --install build --config Release >cmake-install.log
lib_dir=$(dirname "$(find "$PWD/install" -name 'libmoordyn.so*' | head -n 1)")
# The extension finds libmoordyn by an rpath (the wheel workflow uses LD_LIBRARY_PATH and auditwheel).
LDFLAGS="-Wl,-rpath,$lib_dir" "$venv/bin/pip" wheel --quiet --no-deps --no-build-isolation -w dist .
end=$(date +%s.%N)
"$venv/bin/pip" install --quiet dist/moordyn-*.whl
echo "moordyn $tag built in $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.0f", b - a }') s (wall)" \
    | tee "$venv/build_time.txt"
(cd / && "$venv/bin/python" -c "import moordyn, cmoordyn; print(\"installed:\", moordyn.__file__, cmoordyn.__file__)")
