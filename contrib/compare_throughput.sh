#!/usr/bin/env bash
# Side-by-side throughput of two psmpm executables on the 320,000-particle
# bar (prm/benchmark_throughput.prm), alternating runs on one core, for
# lumped P1 and the Powell-Sabin default. Reports, never fails.
#   contrib/compare_throughput.sh OLD_BINARY NEW_BINARY [repetitions] [steps]
# e.g. with the previous release built in ../base:
#   git worktree add ../base <revision> && cmake -S ../base -B ../base/build \
#     -DCMAKE_BUILD_TYPE=Release && cmake --build ../base/build --target psmpm
#   contrib/compare_throughput.sh ../base/build/psmpm build/psmpm 3
# Columns: particle-steps per second of the time loop (summary.json), CPU
# seconds (user + system) and wall seconds of the whole process, peak RSS.
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1; new=$2; reps=${3:-3}; steps=${4:-100}
end=$(/usr/bin/python3 -c "print($steps * 1e-5)")
printf "case\tbinary\trun\tparticle_steps_per_s\tcpu_s\twall_s\tmax_rss_MiB\n"
for case in "lumped P1:Basis/Type=linear:Mass matrix/Type=lumped" \
            "PS default:Basis/Type=powell-sabin:Mass matrix/Type=partially lumped"; do
  IFS=: read -r name basis mass <<< "$case"
  for r in $(seq "$reps"); do
    for which in old new; do
      bin=$old; [ "$which" = new ] && bin=$new
      dir=$(mktemp -d)
      /usr/bin/time -f "%U %S %e %M" -o "$dir/time" taskset -c 0 "$bin" \
        prm/benchmark_throughput.prm --set "$basis" --set "$mass" \
        --set "Time/End time=$end" --set "Output directory=$dir/out" \
        > /dev/null
      /usr/bin/python3 - "$dir" "$name" "$which" "$r" <<'PY'
import json, sys
d, name, which, r = sys.argv[1:]
u, s, e, m = open(d + "/time").read().split()
j = json.load(open(d + "/out/summary.json"))
print("\t".join([name, which, r, "%.3e" % j["particle_steps_per_second"],
                 "%.2f" % (float(u) + float(s)), e, "%.0f" % (int(m) / 1024)]))
PY
      rm -rf "$dir"
    done
  done
done
