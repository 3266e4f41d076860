#!/usr/bin/env bash
# MPI scaling (reports, never fails): the throughput bar of
# prm/benchmark_throughput.prm with 14 x 14 particles per block (980,000
# particles), STEPS steps (default 100), P1 lumped and the Powell-Sabin
# default (closed bar: partially lumped, musl), on each number of ranks in
# RANKS (default "1 2 3 4"; ranks beyond the cores, nproc, are run with
# --oversubscribe and marked). Each row is the fastest of REPEATS runs
# (default 2) by the wall time of the time loop (summary.json time_loop_s;
# the machine is shared, and the minimum is the least disturbed run).
# Prints a markdown table: loop wall time, speed-up over 1 rank, the CPU
# seconds of that run (user + sys of all processes, /usr/bin/time around
# mpirun) and the final checkpoint's wall time on rank 0.
#
#   bash contrib/mpi_scaling.sh [psmpm binary [psmpm options...]]
# e.g. the distributed mesh (P1 only):
#   BASES="linear:lumped" RANKS="1 2" bash contrib/mpi_scaling.sh \
#     build/psmpm --set "Mesh/Distribution=distributed"
#   environment: BASES ("linear:lumped powell-sabin:automatic")
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/psmpm}
shift || true
steps=${STEPS:-100}
repeats=${REPEATS:-2}
ranks_list=${RANKS:-1 2 3 4}
cores=$(nproc)
end_time=$(/usr/bin/python3 -c "print($steps * 1e-5)")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "| basis, mass | ranks | loop wall s | speed-up | CPU s (user + sys) | checkpoint s |"
echo "|---|---|---|---|---|---|"
for basis in ${BASES:-linear:lumped powell-sabin:automatic}; do
  b=${basis%%:*}
  m=${basis##*:}
  one=
  for ranks in $ranks_list; do
    extra=()
    mark=""
    if [ "$ranks" -gt "$cores" ]; then
      extra=(--oversubscribe)
      mark=" (oversubscribed)"
    fi
    best=
    for _ in $(seq "$repeats"); do
      dir=$(mktemp -d)
      /usr/bin/time -f "%U %S" -o "$dir.time" mpirun "${extra[@]}" -np "$ranks" \
        "$bin" prm/benchmark_throughput.prm --set "Basis/Type=$b" \
        --set "Mass matrix/Type=$m" --set "Particles/Per block x=14" \
        --set "Particles/Per block y=14" --set "Time/End time=$end_time" \
        --set "Output directory=$dir" "$@" > /dev/null
      row=$(/usr/bin/python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
u, s = map(float, open(sys.argv[2]).read().split()[-2:])
print(j['time_loop_s'], '%.2f' % (u + s), '%.2f' % j['timers_s']['checkpoint'])
" "$dir/summary.json" "$dir.time")
      rm -rf "$dir" "$dir.time"
      if [ -z "$best" ] || /usr/bin/python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) < float(sys.argv[2]) else 1)" "${row%% *}" "${best%% *}"; then
        best=$row
      fi
    done
    read -r loop cpu checkpoint <<< "$best"
    [ -z "$one" ] && one=$loop
    speedup=$(/usr/bin/python3 -c "print('%.2f' % ($one / $loop))")
    printf "| %s, %s | %d%s | %.2f | %s | %s | %s |\n" "$b" "$m" "$ranks" "$mark" "$loop" "$speedup" "$cpu" "$checkpoint"
  done
done
