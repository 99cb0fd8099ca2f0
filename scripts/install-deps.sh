#!/usr/bin/env bash
# Installs the Debian packages pumpd needs, only those missing (make run / make test call it).
set -euo pipefail
packages=(g++ cmake make pkg-config libdeal.ii-dev libeigen3-dev libhdf5-dev libhdf5-openmpi-dev
          libgtest-dev numdiff gmsh python3-matplotlib libopenblas0
          libsuitesparse-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "pumpd: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
