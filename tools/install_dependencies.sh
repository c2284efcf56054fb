#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those that are missing.
#   usage: install_dependencies.sh [main|tests]
set -euo pipefail
packages=(cmake make g++ ccache libcgal-dev libcgal-demo libeigen3-dev libboost-dev libspectra-dev
          libsuitesparse-dev libscotch-dev libopenblas-dev libtbb-dev zlib1g-dev pybind11-dev python3-pybind11 python3-numpy python3-dev)
if [ "${1:-main}" = tests ]; then
  packages+=(doxygen python3 python3-meshio python3-vtk9 python3-numpy python3-pytest libopenmesh-dev libcgal-qt5-dev
             pkg-config openmpi-bin libpetsc-complex-dev libslepc-complex-dev qt6-base-dev libqt6opengl6-dev
             python3-venv python3-pip python3-setuptools python3-scipy mypy)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
fi
