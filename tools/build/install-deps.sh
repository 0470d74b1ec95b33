#!/usr/bin/env bash
# Installs the Debian packages choc needs, only when some are missing.
# Usage: tools/build/install-deps.sh [--with-viz] [--with-peer]
#   --with-peer: CalculiX (calculix-ccx) for `make bench-peer` only, never for the tests
set -euo pipefail
pkgs=(build-essential cmake trilinos-all-dev libptscotch-dev libscotch-dev libmumps-dev
      libexodusii-dev libnetcdf-dev openmpi-bin libopenmpi-dev libgtest-dev
      libopenblas0-serial  # optimised BLAS/LAPACK (MUMPS factors by dgemm); serial: no threads under MPI
      gmsh libgmsh-dev
      python3 python3-numpy python3-matplotlib python3-netcdf4
      clang libclang-rt-14-dev)  # libFuzzer for tests/reliability (fuzz.sh)
for opt in "$@"; do
  case "$opt" in
    --with-viz) pkgs+=(paraview python3-paraview xvfb xauth) ;;
    --with-peer) pkgs+=(calculix-ccx) ;;
    *) echo "install-deps: unknown option $opt (--with-viz, --with-peer)" >&2; exit 1 ;;
  esac
done
missing=()
for p in "${pkgs[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
