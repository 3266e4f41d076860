#!/usr/bin/env bash
# Set up, build and run psmpm on Debian 12.
#   contrib/psmpm.sh run [scene.prm] [psmpm options]   default scene if no file
#   contrib/psmpm.sh test [ctest options]              the whole test suite
#   contrib/psmpm.sh build                             only install and build
#   contrib/psmpm.sh tools                             also ParaView (pvbatch) and
#                                                      xvfb for contrib/render/*.py
# Installs missing Debian packages first (needs root or sudo). The build
# directory is $PSMPM_BUILD_DIR (default: build/ in the source tree).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${PSMPM_BUILD_DIR:-$root/build}
mode=${1:-run}
[ $# -gt 0 ] && shift

# numpy, scipy and matplotlib: the contrib/ study scripts (Debian's
# /usr/bin/python3).
packages=(libdeal.ii-dev cmake g++ make ccache perl numdiff openmpi-bin
          libbenchmark-dev python3-numpy python3-scipy python3-matplotlib)
[ "$mode" = tools ] && packages+=(python3-paraview paraview xvfb xauth)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" \
    || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "psmpm: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq \
    --no-install-recommends "${missing[@]}"
fi

# Open MPI refuses to start as root unless told that this is intended.
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
export OMPI_MCA_rmaps_base_oversubscribe=1
# The tests' Open MPI settings (tests/CMakeLists.txt): ranks that wait
# yield their core (on a busy or oversubscribed machine a spinning rank
# takes the core its partner needs); the ob1 messaging layer and no daemon
# for a process started without mpirun, so that its MPI_Init takes 0.08 s
# instead of 0.48 s.
export OMPI_MCA_mpi_yield_when_idle=1 OMPI_MCA_pml=ob1
export OMPI_MCA_ess_singleton_isolated=1

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
# The tests' precompiled header is built here, once, before ctest runs
# tests (and their builds) in parallel; for the whole suite, every test
# program too (ctest then only runs them).
targets=(psmpm)
[ "$mode" = test ] && targets+=(psmpm_test_pch)
[ "$mode" = test ] && [ $# -eq 0 ] && targets+=(psmpm_test_programs)
cmake --build "$build" --target "${targets[@]}" -- -j2

case "$mode" in
  run)   exec "$build/psmpm" "$@" ;;
  test)  cd "$build" && exec ctest -j2 --output-on-failure "$@" ;;
  build|tools) ;;
  *)     echo "usage: $0 run|test|build|tools" >&2; exit 2 ;;
esac
