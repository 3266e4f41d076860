#!/usr/bin/env bash
# Performance report (reports, never fails): every basis x mass matrix
# strategy x transfer scheme on the throughput bar of
# prm/benchmark_throughput.prm (320,000 particles, closed), STEPS steps
# (default 40, the scene's) of 1e-5 s, one process pinned to core 0, one
# run each (80 runs, about 6 minutes).
# Bases: linear, powell-sabin. Mass: automatic and every strategy of
# Mass matrix/Type. Transfer: automatic, musl, usl, apic, otm. A
# combination psmpm refuses (bad input, exit 2: otm with ghost penalty,
# say) or that stops unstable is listed with its status and exit code.
# Columns: the requested and the resolved strategy and scheme (automatic
# names the basis' default), status, exit code, particle-steps per second
# (wall time of the time loop's phases, output and checkpoints left out),
# CPU microseconds per particle-step (summary.json cpu_time_loop_s: the
# CPU time of the loop, robust to other load on the machine, but with the
# output and checkpoint written after the last step, about 0.1-0.4 s
# here, which short runs should keep in mind), loop wall s, run CPU s
# (user + sys, set-up included), peak RSS MiB, CG iterations per step and
# the loop's phases in seconds (summary.json timers_s). Writes $OUT (default
# doc/data/performance_report.tsv) and prints it as a table.
#
#   [STEPS=40] [OUT=...] bash contrib/benchmarks/performance_report.sh [psmpm binary]
set -uo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-${PSMPM_BINARY:-build/psmpm}}
steps=${STEPS:-40}
out=${OUT:-doc/data/performance_report.tsv}
end=$(/usr/bin/python3 -c "print($steps * 1e-5)")
mkdir -p "$(dirname "$out")"
bash contrib/benchmarks/machine.sh
phases="locate particle_to_grid solve grid_to_particle update statistics"
{
  printf "basis\tmass_requested\tmass\ttransfer_requested\ttransfer\tstatus\texit_code"
  printf "\tparticle_steps_per_s\tcpu_us_per_particle_step\tloop_s\tcpu_s\tmax_rss_mib\tcg_per_step"
  for p in $phases; do printf "\t%s_s" "$p"; done
  printf "\n"
} > "$out"
masses=("automatic" "lumped" "consistent" "partially lumped" "extrapolate"
        "ghost penalty" "fictitious mass" "blended lumping")
for basis in linear powell-sabin; do
  for mass in "${masses[@]}"; do
    for transfer in automatic musl usl apic otm; do
      dir=$(mktemp -d)
      /usr/bin/time -f "%U %S %M" -o "$dir/time" taskset -c 0 "$bin" \
        prm/benchmark_throughput.prm --set "Basis/Type=$basis" \
        --set "Mass matrix/Type=$mass" --set "Transfer/Scheme=$transfer" \
        --set "Time/End time=$end" --set "Output/Interval=0" \
        --set "Output directory=$dir/out" > "$dir/log" 2>&1
      code=$?
      /usr/bin/python3 - "$dir" "$basis" "$mass" "$transfer" "$code" \
        "$phases" >> "$out" <<'PY'
import json, sys
d, basis, mass, transfer, code, phases = sys.argv[1:]
row = [basis, mass]
try:
    u, s, m = open(d + "/time").read().split()[-3:]
    cpu, rss = "%.2f" % (float(u) + float(s)), "%.0f" % (int(m) / 1024)
except Exception:
    cpu, rss = "nan", "nan"
try:
    j = json.load(open(d + "/out/summary.json"))
except Exception:
    # Refused before the run (bad input): no summary.json is written.
    print("\t".join(row + ["-", transfer, "-", "refused", code] +
                    ["nan"] * 7 + ["nan"] * len(phases.split())))
    sys.exit()
n = j.get("steps", 0) * j.get("n_particles", 0)
t = j.get("timers_s", {})
print("\t".join(row + [j.get("mass_matrix", "-"), transfer,
                       j.get("transfer", "-"), j.get("status", "-"), code,
                       "%.3e" % j.get("particle_steps_per_second", 0),
                       "%.3f" % (1e6 * j["cpu_time_loop_s"] / n) if n else "nan",
                       "%.3f" % j.get("time_loop_s", 0), cpu, rss,
                       "%.1f" % (j.get("cg_iterations", 0) / max(1, j.get("steps", 1)))] +
                ["%.3f" % t.get(p, 0) for p in phases.split()]))
PY
      rm -rf "$dir"
    done
  done
done
column -t -s $'\t' "$out"
