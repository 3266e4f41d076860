#!/usr/bin/env bash
# Peak resident memory of each MPI rank against the number of ranks, on a
# large mesh with few particles (so that the per-cell data decide it):
# the throughput bar's mesh refined to NX x NY criss-cross blocks (4
# triangles each), 2 x 2 particles per block in a 0.5 x 0.5 corner, one
# step. One line per (basis, ranks, rank): peak RSS (MiB, /usr/bin/time's
# %M of that rank's process), its CPU (user + sys) and wall seconds.
# Reports, never fails. Ranks beyond the cores are oversubscribed.
#   contrib/benchmarks/rank_memory.sh [BINARY [psmpm options...]]   (default build/psmpm)
# e.g. the Taylor least squares rules:
#   contrib/benchmarks/rank_memory.sh build/psmpm --set "Transfer/Scheme=musl" \
#     --set "Transfer/Reconstruction=taylor least squares"
#   environment: NX (1000), NY (80), RANKS ("1 2"), BASES ("linear powell-sabin")
set -uo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/psmpm}
shift || true
NX=${NX:-1000}; NY=${NY:-80}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
printf "basis\tcells\tranks\trank\tpeak_MiB\tcpu_s\twall_s\n"
for basis in ${BASES:-linear powell-sabin}; do
  for np in ${RANKS:-1 2}; do
    mpirun -np "$np" bash -c '/usr/bin/time -o "$0.$OMPI_COMM_WORLD_RANK" \
        -f "%M %U %S %e" "$@"' "$work/time" "$bin" prm/benchmark_throughput.prm \
      --set "Basis/Type=$basis" --set "Mesh/Blocks x=$NX" \
      --set "Mesh/Blocks y=$NY" --set "Particles/Region=0, 0, 0.5, 0.5" \
      --set "Particles/Per block x=2" --set "Particles/Per block y=2" \
      --set "Time/End time=1e-5" --set "Output directory=$work/out" "$@" \
      > "$work/log" 2>&1 || { echo "run failed: $basis, $np ranks"; tail -5 "$work/log"; }
    for ((r = 0; r < np; ++r)); do
      read -r kb user sys wall < "$work/time.$r"
      awk -v b="$basis" -v c=$((4 * NX * NY)) -v n="$np" -v r="$r" -v kb="$kb" \
        -v u="$user" -v s="$sys" -v w="$wall" \
        'BEGIN { printf "%s\t%d\t%d\t%d\t%.0f\t%.2f\t%.2f\n", b, c, n, r, kb / 1024, u + s, w }'
    done
  done
done
rm -rf "$work"
