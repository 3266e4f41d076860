#!/usr/bin/env bash
# MPI scaling (reports, never fails): the throughput bar of
# prm/benchmark_throughput.prm with 14 x 14 particles per block (980,000
# particles), STEPS steps (default 100), P1 lumped and the Powell-Sabin
# default (closed bar: partially lumped, musl), on each number of ranks in
# RANKS (default "1 2 3 4"; ranks beyond the cores, nproc, are run with
# --oversubscribe and marked). Each row is the fastest of REPEATS runs
# (default 2) by the wall time of the time loop (summary.json time_loop_s;
# the machine is shared, and the minimum is the least disturbed run).
# The runs go in rounds, each round every rank count once in turn, so
# that the runs a ratio compares are minutes apart at most: this machine's
# speed drifts by a third within minutes, in every phase alike (doc/
# performance.md, "Machines"). Prints a markdown table: the
# fastest run's loop wall time, its speed-up over the fastest 1-rank run,
# the median and range of the speed-ups within a round (the 1-rank run
# against the run of this rank count in the same round), the fastest
# run's CPU seconds (user + sys of all processes, /usr/bin/time around
# mpirun) and its final checkpoint's wall time on rank 0. The last two
# columns say how much the rest of the machine took during that run, from
# /proc/stat: "others" is the CPU seconds all processes of the machine used
# (user, nice, system, irq, softirq) minus this run's own, and "steal" the
# seconds the hypervisor gave the virtual cores to other guests. Both are
# zero on a quiet machine; where they are not, the run was disturbed.
#
#   bash contrib/benchmarks/mpi_scaling.sh [psmpm binary [psmpm options...]]
# e.g. the distributed mesh (P1 only):
#   BASES="linear:lumped" RANKS="1 2" bash contrib/benchmarks/mpi_scaling.sh \
#     build/psmpm --set "Mesh/Distribution=distributed"
#   environment: BASES ("linear:lumped powell-sabin:automatic")
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/psmpm}
shift || true
steps=${STEPS:-100}
repeats=${REPEATS:-2}
ranks_list=${RANKS:-1 2 3 4}
cores=$(nproc)
end_time=$(/usr/bin/python3 -c "print($steps * 1e-5)")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
bash contrib/benchmarks/machine.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { # basis mass ranks: prints "loop cpu checkpoint others steal"
  local dir=$work/run extra=()
  [ "$3" -gt "$cores" ] && extra=(--oversubscribe)
  rm -rf "$dir"
  head -1 /proc/stat > "$work/stat"
  /usr/bin/time -f "%U %S" -o "$work/time" mpirun "${extra[@]}" -np "$3" \
    "$bin" prm/benchmark_throughput.prm --set "Basis/Type=$1" \
    --set "Mass matrix/Type=$2" --set "Particles/Per block x=14" \
    --set "Particles/Per block y=14" --set "Time/End time=$end_time" \
    --set "Output directory=$dir" "${options[@]}" > /dev/null || exit
  head -1 /proc/stat >> "$work/stat"
  /usr/bin/python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
u, s = map(float, open(sys.argv[2]).read().split()[-2:])
# /proc/stat: cpu user nice system idle iowait irq softirq steal, in
# 1/100 s (USER_HZ).
a, b = [list(map(int, l.split()[1:9])) for l in open(sys.argv[3])]
d = [(y - x) / 100.0 for x, y in zip(a, b)]
busy = d[0] + d[1] + d[2] + d[5] + d[6]
print(j['time_loop_s'], '%.2f' % (u + s), '%.2f' % j['timers_s']['checkpoint'],
      '%.2f' % max(busy - u - s, 0.0), '%.2f' % d[7])
" "$dir/summary.json" "$work/time" "$work/stat"
}
options=("$@")
echo "| basis, mass | ranks | loop wall s (fastest) | speed-up (fastest) | speed-up within a round: median (range) | CPU s (user + sys) | checkpoint s | others CPU s | steal s |"
echo "|---|---|---|---|---|---|---|---|---|"
for basis in ${BASES:-linear:lumped powell-sabin:automatic}; do
  b=${basis%%:*}
  m=${basis##*:}
  : > "$work/rows"
  for round in $(seq "$repeats"); do
    for ranks in $ranks_list; do
      row=$(run "$b" "$m" "$ranks") # a failed run stops the script (set -e)
      echo "$ranks $round $row" >> "$work/rows"
    done
  done
  /usr/bin/python3 - "$work/rows" "$b, $m" "$cores" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
ranks = list(dict.fromkeys(int(r[0]) for r in rows))
loop = {(int(r[0]), int(r[1])): float(r[2]) for r in rows}
def fastest(n):
    return min((r for r in rows if int(r[0]) == n), key=lambda r: float(r[2]))
one = float(fastest(ranks[0])[2])
for n in ranks:
    f = fastest(n)
    paired = sorted(loop[(ranks[0], k)] / loop[(n, k)] for (m, k) in loop if m == n)
    mark = " (oversubscribed)" if n > int(sys.argv[3]) else ""
    print("| %s | %d%s | %.2f | %.2f | %.2f (%.2f-%.2f) | %s | %s | %s | %s |" % (
        sys.argv[2], n, mark, float(f[2]), one / float(f[2]),
        statistics.median(paired), paired[0], paired[-1], f[3], f[4], f[5], f[6]))
PY
done
