#!/usr/bin/env bash
# Shared set-up for run.sh and test.sh: install missing Debian packages, configure and build
# Release into build/. Sourced, so the callers keep `set -euo pipefail`.
packages=(cmake g++ make libsystemc-dev libglm-dev libopenimageio-dev catch2 libcli11-dev
          nlohmann-json3-dev libassimp-dev pkg-config libtomlplusplus-dev python3-matplotlib
          slurm-wlm munge verilator zlib1g-dev gtkwave xvfb imagemagick
          webp assimp-testmodels time clang-format libembree-dev)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$package")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -eq 0 ]]; then
    echo "rtusim: installing ${missing[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
  else
    echo "rtusim: missing packages. Install them with:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi

root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# RTUSIM_UNITY_BUILD: a from-scratch build in fewer translation units (CMakeLists.txt).
cmake -S "$root_dir" -B "$root_dir/build" -DCMAKE_BUILD_TYPE=Release -DRTUSIM_UNITY_BUILD=ON >/dev/null
cmake --build "$root_dir/build" -j "$(nproc)"
