#!/usr/bin/env bash
# Throughput benchmark (reports, never fails): the 320,000-particle bar of
# prm/benchmark_throughput.prm, 40 steps, one process pinned to one core.
# Rows: P1 lumped and consistent, and the defaults (automatic) of both
# bases on the closed bar (partially lumped, musl) and on the same bar
# with free boundaries (P1: ghost penalty, musl; Powell-Sabin: lumped,
# apic). Writes doc/data/throughput.tsv (or $OUT): particle-steps per second (wall
# time of the time loop, per-step statistics included), CPU seconds of the whole run (user + sys, setup
# included), peak memory and the TimerOutput breakdown from summary.json.
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${PSMPM_BINARY:-build/psmpm}
out=${OUT:-doc/data/throughput.tsv}
mkdir -p "$(dirname "$out")"
bash contrib/benchmarks/machine.sh
printf "basis\tboundaries\tmass_matrix\ttransfer\tparticles\tsteps\tparticle_steps_per_s\tcpu_s\tmax_rss_mib\tlocate_s\tparticle_to_grid_s\tsolve_s\tgrid_to_particle_s\tupdate_s\tstatistics_s\ttime_loop_s\n" > $out
run() { # basis mass transfer closed|free
  local dir extra=()
  dir=$(mktemp -d)
  [ "$4" = free ] && extra=(--set "Boundary conditions/Fixed x=" --set "Boundary conditions/Fixed y=")
  /usr/bin/time -f "%U %S %M" -o "$dir.time" taskset -c 0 "$bin" prm/benchmark_throughput.prm \
    --set "Basis/Type=$1" --set "Mass matrix/Type=$2" --set "Transfer/Scheme=$3" \
    "${extra[@]}" --set "Output directory=$dir" > /dev/null
  /usr/bin/python3 - "$dir/summary.json" "$dir.time" "$1" "$4" >> $out <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); t = s["timers_s"]
u, y, rss = open(sys.argv[2]).read().split()[-3:]
print("\t".join([sys.argv[3], sys.argv[4], s["mass_matrix"], s["transfer"],
  str(s["n_particles"]), str(s["steps"]), "%.3e" % s["particle_steps_per_second"],
  "%.2f" % (float(u) + float(y)), "%.0f" % (float(rss) / 1024)] +
  ["%.3f" % t[k] for k in ["locate", "particle_to_grid", "solve", "grid_to_particle", "update", "statistics"]] +
  ["%.3f" % s["time_loop_s"]]))
PY
  rm -rf "$dir" "$dir.time"
}
run linear lumped musl closed
run linear consistent musl closed
run linear automatic automatic closed
run powell-sabin automatic automatic closed
run linear automatic automatic free
run powell-sabin automatic automatic free
column -t -s $'\t' $out
