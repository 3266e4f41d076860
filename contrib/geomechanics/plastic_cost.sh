#!/usr/bin/env bash
# The cost of the soil models against the elastic one on the throughput bar
# (prm/benchmark_throughput.prm: 320,000 particles, P1, lumped mass, MUSL):
# each pair of runs side by side, one per core (taskset), so that both see
# the same machine; rate (particle-steps per second), the CPU and wall
# seconds of the steps (summary.json's cpu_time_steps_s and time_loop_s:
# without the output and the checkpoint at the end, which cost about a
# second on the bar whatever the material) and the update phase's seconds,
# and the ratio of the steps' CPU seconds, soil model over elastic (per
# round, and at the end every case's rounds and their median).
#   bash contrib/geomechanics/plastic_cost.sh [build/psmpm] [rounds] \
#     [steps] [--set "entry=value" ...]
# The --set entries go to both runs of a pair (another basis, mass or
# transfer).
# Cases: hypoelastic; mohr-coulomb and drucker-prager far from yield
# (Cohesion 1e9: the elastic path with the yield test); mohr-coulomb and
# drucker-prager yielding in every particle and step (Tresca / von Mises,
# Cohesion 1e-6 Pa, below the bar's stresses from the first steps).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
binary=${1:-$root/build/psmpm}
rounds=${2:-3}
steps=${3:-400}
shift $(($# < 3 ? $# : 3))
common=("$@")
end_time=$(/usr/bin/python3 -c "print($steps * 1e-5)")
work=$(mktemp -d)
# Each run writes its first and last VTU output (about 140 MB on the bar):
# removed after each pair, and all of it on any exit.
trap 'rm -rf "$work"' EXIT
run() { # core name args...
  local core=$1 name=$2
  shift 2
  taskset -c "$core" "$binary" "$root/prm/benchmark_throughput.prm" \
    --set "Output directory=$work/$name" --set "Time/End time=$end_time" \
    "${common[@]}" "$@" > /dev/null 2>&1
}
report() { # elastic-run soil-run
  /usr/bin/python3 - "$work" "$1" "$2" <<'PY'
import json, sys
work, names = sys.argv[1], sys.argv[2:]
s = [json.load(open(f"{work}/{n}/summary.json")) for n in names]
for n, x in zip(names, s):
    print(f"{n:28s} rate {x['particle_steps_per_second']:.3e}  "
          f"steps CPU {x['cpu_time_steps_s']:.2f} s  wall {x['time_loop_s']:.2f} s  "
          f"update {x['timers_s']['update']:.2f} s  status {x['status']}")
ratio = s[1]['cpu_time_steps_s'] / s[0]['cpu_time_steps_s']
print(f"{'ratio (steps CPU)':28s} {ratio:.3f}")
with open(f"{work}/ratios", "a") as f:
    f.write(f"{names[1]} {ratio:.3f}\n")
PY
}
summary() { # every case's ratios over the rounds and their median
  /usr/bin/python3 - "$work/ratios" <<'PY'
import statistics, sys
ratios = {}
for line in open(sys.argv[1]):
    name, r = line.split()
    ratios.setdefault(name, []).append(float(r))
print("steps CPU, soil model / elastic model, per round; median:")
for name, r in ratios.items():
    print(f"{name:28s} {', '.join(f'{x:.2f}' for x in r)}; "
          f"{statistics.median(r):.2f}")
PY
}
elastic=(--set "Material/Model=hypoelastic")
for round in $(seq "$rounds"); do
  for case in "mohr-coulomb elastic:Material/Model=mohr-coulomb:Material/Cohesion=1e9" \
              "drucker-prager elastic:Material/Model=drucker-prager:Material/Cohesion=1e9" \
              "mohr-coulomb yielding:Material/Model=mohr-coulomb:Material/Cohesion=1e-6" \
              "drucker-prager yielding:Material/Model=drucker-prager:Material/Cohesion=1e-6"; do
    IFS=: read -r name model cohesion <<< "$case"
    tag=${name// /_}
    args=(--set "$model" --set "$cohesion" --set "Material/Friction angle=0")
    # Swap the cores every round.
    if [ $((round % 2)) -eq 1 ]; then
      run 0 "hypo_$tag" "${elastic[@]}" & run 1 "$tag" "${args[@]}" & wait
    else
      run 1 "hypo_$tag" "${elastic[@]}" & run 0 "$tag" "${args[@]}" & wait
    fi
    echo "round $round:"
    report "hypo_$tag" "$tag"
    rm -rf "${work:?}/hypo_$tag" "${work:?}/$tag"
  done
done
summary
