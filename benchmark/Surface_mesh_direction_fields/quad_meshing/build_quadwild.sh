#!/bin/bash
# Builds QuadWild (the Bi-MDF fork: `quadwild` and `quad_from_patches`) from the
# read-only sources in ../shared/clients/quadwild-bimdf into OUT/bin, with
# Debian's Eigen, OpenMesh and gmm++. The sources are copied to OUT/src (the
# quad-meshing runs start there so that QuadWild's config paths resolve).
# For the quad-meshing benchmark only, not CI: 10-20 minutes on 2 cores.
#   build_quadwild.sh OUT [SOURCES]
set -euo pipefail
out=$(realpath -m "${1:?usage: build_quadwild.sh OUT [SOURCES]}")
here=$(cd "$(dirname "$0")" && pwd)
sources=${2:-$here/../../../../shared/clients/quadwild-bimdf}
[ -d "$sources/components" ] || { echo "no QuadWild sources at $sources" >&2; exit 1; }

missing=()
for package in cmake g++ libeigen3-dev libopenmesh-dev libgmm++-dev libboost-filesystem-dev \
               libboost-system-dev libboost-regex-dev liblapack-dev; do
  dpkg -s "$package" >/dev/null 2>&1 || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  apt-get update -q && apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

mkdir -p "$out"
rm -rf "$out/src"
cp -r "$sources" "$out/src"
# QuadWild's CMakeLists points Eigen3::Eigen at libs/eigen (a submodule not
# kept in the shared copy): Debian's Eigen stands in for it.
[ -e "$out/src/libs/eigen" ] || ln -s /usr/include/eigen3 "$out/src/libs/eigen"

cmake -S "$out/src" -B "$out/build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_FLAGS="-w" -DCMAKE_C_FLAGS="-w" > "$out/configure.log"
cmake --build "$out/build" -j "$(nproc)" --target quadwild quad_from_patches > "$out/build.log"
mkdir -p "$out/bin"
for program in quadwild quad_from_patches; do
  cp "$(find "$out/build" -type f -name "$program" -perm -u+x | head -n 1)" "$out/bin/$program"
done
echo "built $out/bin/quadwild and $out/bin/quad_from_patches"
