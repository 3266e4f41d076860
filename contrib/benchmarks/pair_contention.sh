#!/usr/bin/env bash
# Shared-resource ceiling for the two-rank target (reports, never fails):
# the 980,000-particle throughput bar of contrib/benchmarks/mpi_scaling.sh (P1 lumped
# unless BASIS/MASS say otherwise), STEPS steps, run once alone on core 0
# and then twice at the same time, one process per core, with no MPI
# between them. If the pair's runs are slower than the lone one, the two
# cores share something (memory bandwidth, the host) that no change of
# the communication can win back: 2 x alone / pair bounds what two ranks
# can reach. Each round prints the loop wall times (summary.json
# time_loop_s), each process's CPU seconds (user + sys, /usr/bin/time)
# and that bound.
#
#   [REPEATS=2] [STEPS=100] [BASIS=linear] [MASS=lumped] \
#     bash contrib/benchmarks/pair_contention.sh [psmpm binary]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/psmpm}
repeats=${REPEATS:-2}
steps=${STEPS:-100}
end_time=$(/usr/bin/python3 -c "print($steps * 1e-5)")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { # core directory
  /usr/bin/time -f "%U %S" -o "$2.time" taskset -c "$1" "$bin" prm/benchmark_throughput.prm \
    --set "Basis/Type=${BASIS:-linear}" --set "Mass matrix/Type=${MASS:-lumped}" \
    --set "Particles/Per block x=14" --set "Particles/Per block y=14" \
    --set "Time/End time=$end_time" --set "Output/Interval=0" \
    --set "Output directory=$2" > /dev/null
}
loop() { # directory: loop wall s / run CPU s
  /usr/bin/python3 -c "import json, sys; u, s = map(float, open(sys.argv[2]).read().split()[-2:]); print('%.3f / %.2f' % (json.load(open(sys.argv[1]))['time_loop_s'], u + s))" "$1/summary.json" "$1.time"
}
bash contrib/benchmarks/machine.sh
echo "| round | alone: loop wall s / run CPU s | pair, core 0 | pair, core 1 | 2 x alone / slower of pair (loop wall) |"
echo "|---|---|---|---|---|"
for r in $(seq "$repeats"); do
  run 0 "$work/alone"
  run 0 "$work/pair0" & run 1 "$work/pair1"; wait
  a=$(loop "$work/alone"); p0=$(loop "$work/pair0"); p1=$(loop "$work/pair1")
  bound=$(/usr/bin/python3 -c "print('%.2f' % (2 * ${a%% *} / max(${p0%% *}, ${p1%% *})))")
  echo "| $r | $a | $p0 | $p1 | $bound |"
  rm -rf "$work"/alone* "$work"/pair0* "$work"/pair1*
done
