#!/usr/bin/env bash
# Installs the Debian packages pilempm builds with (DESIGN.md section 7) when some are
# missing. As root it runs apt-get; otherwise it names what to install and fails.
set -euo pipefail

# Trilinos' CMake targets name /usr/lib/.../lib{pt,}scotch.so, which only the scotch -dev
# packages install (trilinos-all-dev does not pull them in).
packages=(build-essential gfortran cmake ninja-build pkg-config libeigen3-dev libhdf5-dev libvtk9-dev
          libgmsh-dev libopenmpi-dev libyaml-cpp-dev libgtest-dev libbenchmark-dev
          trilinos-all-dev libscotch-dev libptscotch-dev python3-matplotlib python3-yaml)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "pilempm needs these Debian packages: ${missing[*]}" >&2
  echo "install them with: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi
echo "installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
