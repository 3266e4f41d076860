#!/usr/bin/env bash
# Side-by-side throughput of two psmpm executables on the 320,000-particle
# bar (prm/benchmark_throughput.prm), for lumped P1 and the Powell-Sabin
# default. Reports, never fails.
#   [PAIRED=1] contrib/benchmarks/compare_throughput.sh OLD_BINARY NEW_BINARY [repetitions] [steps]
# e.g. with the previous release built in ../base:
#   git worktree add ../base <revision> && cmake -S ../base -B ../base/build \
#     -DCMAKE_BUILD_TYPE=Release && cmake --build ../base/build --target psmpm
#   contrib/benchmarks/compare_throughput.sh ../base/build/psmpm build/psmpm 3
# By default the runs alternate on core 0. With PAIRED=1 old and new run
# at the same time, one on each core, the cores swapped every repetition:
# on a virtual machine whose host changes its speed by a third within
# minutes (doc/performance.md, "Machines") both then see
# the same host, provided the two cores do not share their memory
# bandwidth (check with contrib/benchmarks/pair_contention.sh first).
# Columns: particle-steps per second and wall seconds of the time loop
# (summary.json), CPU seconds (user + system) and wall seconds of the
# whole process, peak RSS, the core, then the loop's phases (summary.json
# timers_s: locate, particle to grid, solve, grid to particle, update,
# statistics).
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$1; new=$2; reps=${3:-3}; steps=${4:-100}
end=$(/usr/bin/python3 -c "print($steps * 1e-5)")
printf "case\tbinary\trun\tparticle_steps_per_s\tloop_s\tcpu_s\twall_s\tmax_rss_MiB\tcore\tlocate_s\tparticle_to_grid_s\tsolve_s\tgrid_to_particle_s\tupdate_s\tstatistics_s\n"
run() { # binary case-settings... : one run into $dir on core $core
  local bin=$1; shift
  /usr/bin/time -f "%U %S %e %M" -o "$dir/time" taskset -c "$core" "$bin" \
    prm/benchmark_throughput.prm "$@" \
    --set "Time/End time=$end" --set "Output directory=$dir/out" \
    > /dev/null
}
report() { # directory name which repetition core
  /usr/bin/python3 - "$@" <<'PY'
import json, sys
d, name, which, r, core = sys.argv[1:]
u, s, e, m = open(d + "/time").read().split()
j = json.load(open(d + "/out/summary.json"))
t = j["timers_s"]
print("\t".join([name, which, r, "%.3e" % j["particle_steps_per_second"],
                 "%.3f" % j["time_loop_s"], "%.2f" % (float(u) + float(s)), e,
                 "%.0f" % (int(m) / 1024), core] +
                ["%.3f" % t.get(k, 0) for k in ["locate", "particle_to_grid",
                 "solve", "grid_to_particle", "update", "statistics"]]))
PY
}
for case in "lumped P1:Basis/Type=linear:Mass matrix/Type=lumped" \
            "PS default:Basis/Type=powell-sabin:Mass matrix/Type=partially lumped"; do
  IFS=: read -r name basis mass <<< "$case"
  for r in $(seq "$reps"); do
    if [ "${PAIRED:-0}" = 1 ]; then
      old_dir=$(mktemp -d); new_dir=$(mktemp -d)
      old_core=$(( r % 2 )); new_core=$(( 1 - r % 2 ))
      dir=$old_dir core=$old_core run "$old" --set "$basis" --set "$mass" &
      dir=$new_dir core=$new_core run "$new" --set "$basis" --set "$mass"
      wait
      report "$old_dir" "$name" old "$r" "$old_core"
      report "$new_dir" "$name" new "$r" "$new_core"
      rm -rf "$old_dir" "$new_dir"
      continue
    fi
    for which in old new; do
      bin=$old; [ "$which" = new ] && bin=$new
      dir=$(mktemp -d) core=0
      run "$bin" --set "$basis" --set "$mass"
      report "$dir" "$name" "$which" "$r" 0
      rm -rf "$dir"
    done
  done
done
