#!/usr/bin/env bash
# Two ranks against one (reports, never fails): the throughput bar of
# prm/benchmark_throughput.prm with 14 x 14 particles per block (980,000
# particles), 20 steps, P1 lumped and the Powell-Sabin default (closed bar:
# partially lumped, musl), on 1 and 2 MPI processes. Prints a markdown
# table: wall time of the time loop (summary.json time_loop_s), the speed-up
# of 2 ranks over 1 from it, and the CPU seconds (user + sys of all
# processes, /usr/bin/time around mpirun).
#
#   bash contrib/mpi_scaling.sh [psmpm binary]
#
# The machine has 2 cores; other load on it shows in the speed-up.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/psmpm}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "| basis, mass | ranks | loop wall s | speed-up | CPU s (user + sys) |"
echo "|---|---|---|---|---|"
for basis in "linear lumped" "powell-sabin automatic"; do
  set -- $basis
  one=
  for ranks in 1 2; do
    dir=$(mktemp -d)
    /usr/bin/time -f "%U %S" -o "$dir.time" mpirun -np $ranks "$bin" \
      prm/benchmark_throughput.prm --set "Basis/Type=$1" \
      --set "Mass matrix/Type=$2" --set "Particles/Per block x=14" \
      --set "Particles/Per block y=14" --set "Time/End time=2e-4" \
      --set "Output directory=$dir" > /dev/null
    loop=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['time_loop_s'])" "$dir/summary.json")
    cpu=$(awk '{printf "%.2f", $1 + $2}' "$dir.time")
    [ -z "$one" ] && one=$loop
    speedup=$(/usr/bin/python3 -c "print('%.2f' % ($one / $loop))")
    printf "| %s, %s | %d | %.2f | %s | %s |\n" "$1" "$2" $ranks "$loop" "$speedup" "$cpu"
    rm -rf "$dir" "$dir.time"
  done
done
