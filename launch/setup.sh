#!/usr/bin/env bash
# Installs the Debian packages the project needs. Idempotent: a second run only
# checks that everything is present. Called by the README's two commands and by .ci/run.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  liblcm-dev liblcm-bin
  # lcm.jar and the charts lcm-spy draws with, for `fsi spy` (3 MB with what they
  # pull in); the build makes the message types for it with the JDK when there is one
  liblcm-java libjchart2d-java
  libhdf5-dev hdf5-tools
  libinih-dev
  libsuitesparse-dev
  python3-matplotlib python3-h5py python3-numpy python3-scipy
  paraview python3-paraview
  iproute2 util-linux
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
