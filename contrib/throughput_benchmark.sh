#!/usr/bin/env bash
# Throughput benchmark (reports, never fails): 320,000 particles, P1,
# lumped and consistent, one process pinned to one core.
# Writes doc/data/throughput.tsv with particle-steps per second and the
# TimerOutput breakdown from summary.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${PSMPM_BINARY:-build/psmpm}
out=doc/data/throughput.tsv
mkdir -p doc/data
printf "mass_matrix\tparticles\tsteps\tparticle_steps_per_s\tlocate_s\tparticle_to_grid_s\tsolve_s\tgrid_to_particle_s\tupdate_s\ttime_loop_s\n" > $out
for m in lumped consistent; do
  dir=$(mktemp -d)
  taskset -c 0 "$bin" prm/benchmark_throughput.prm --set "Mass matrix/Type=$m" \
    --set "Output directory=$dir" > /dev/null
  /usr/bin/python3 - "$dir/summary.json" "$m" >> $out <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); t = s["timers_s"]
print("\t".join([sys.argv[2], str(s["n_particles"]), str(s["steps"]),
  "%.3e" % s["particle_steps_per_second"]] +
  ["%.3f" % t[k] for k in ["locate", "particle_to_grid", "solve", "grid_to_particle", "update"]] +
  ["%.3f" % s["time_loop_s"]]))
PY
done
cat $out
