#!/usr/bin/env bash
# Particle output cost, vtu against hdf5 (reports, never fails): the
# 320,000-particle bar of prm/benchmark_throughput.prm, 40 steps, one
# process pinned to one core, each format run with Output/Interval = 0
# (2 outputs) and = 1 (41 outputs). The cost of one output is the
# difference of the two runs' CPU (user + sys) and wall seconds over the
# 39 extra outputs (grid output included, the same VTU in both formats);
# its size is that of the particle files of the last output (vtu: the
# pieces and the .pvtu; hdf5: the .h5). PSMPM_RANKS=N runs on N MPI ranks
# instead (CPU seconds summed over the ranks). Usage:
#   bash contrib/benchmarks/particle_output_benchmark.sh [work directory]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${PSMPM_BINARY:-build/psmpm}
work=${1:-$(mktemp -d)}
ranks=${PSMPM_RANKS:-1}
mkdir -p "$work"
if [ "$ranks" -gt 1 ]; then
  launch=(mpirun -np "$ranks")
else
  launch=(taskset -c 0)
fi
run() { # format interval -> "user sys wall" in $work/<format>-<interval>.time
  local dir=$work/$1-$2
  rm -rf "$dir"
  /usr/bin/time -f "%U %S %e" -o "$dir.time" "${launch[@]}" "$bin" \
    prm/benchmark_throughput.prm --set "Output/Particle format=$1" \
    --set "Output/Interval=$2" --set "Output directory=$dir" > /dev/null
}
# Alternating, so that a change in the machine's load hits both formats.
for interval in 0 1; do
  for format in vtu hdf5; do
    run $format $interval
  done
done
printf "format\tparticle_bytes_per_output\tcpu_s_per_output\twall_s_per_output\tcpu_s_2_outputs\tcpu_s_41_outputs\n"
for format in vtu hdf5; do
  if [ $format = vtu ]; then
    bytes=$(cat "$work/vtu-1"/particles-00040.*vtu | wc -c)
  else
    bytes=$(wc -c < "$work/hdf5-1/particles-00040.h5")
  fi
  read -r u0 s0 w0 < <(tail -1 "$work/$format-0.time")
  read -r u1 s1 w1 < <(tail -1 "$work/$format-1.time")
  /usr/bin/python3 -c "
import sys
u0, s0, w0, u1, s1, w1 = map(float, sys.argv[3:])
print('%s\t%s\t%.3f\t%.3f\t%.2f\t%.2f' % (sys.argv[1], sys.argv[2],
      (u1 + s1 - u0 - s0) / 39, (w1 - w0) / 39, u0 + s0, u1 + s1))" \
    $format "$bytes" "$u0" "$s0" "$w0" "$u1" "$s1" "$w1"
done
