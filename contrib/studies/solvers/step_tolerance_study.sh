#!/usr/bin/env bash
# What the time step needs of the mass solves: CG iterations, errors and
# CPU seconds against Mass matrix/Step tolerance (0 = the old test,
# ||r|| <= Solver tolerance ||b|| alone) on three scenes whose mass
# systems go through CG:
# * throughput: the 320,000-particle bar of prm/benchmark_throughput.prm,
#   Powell-Sabin default (partially lumped), 40 steps; its statistics at
#   the end (kinetic energy, strain energy, angular momentum);
# * bar 64x4: prm/vibrating_bar_large.prm on 64 x 4 blocks, 4 x 4
#   particles per block, partially lumped, every system through CG
#   (Direct solver size = 0), 5 s: errors against the ULFEM reference;
# * large bar: prm/vibrating_bar_large.prm as it is (consistent mass,
#   35,000 steps) with every system through CG.
# CPU = user + sys of the run. Reports, never fails.
#   contrib/studies/solvers/step_tolerance_study.sh [psmpm binary] [tolerances...]
set -uo pipefail
cd "$(dirname "$0")/../../.."
bin=${1:-build/psmpm}
shift || true
tolerances=${*:-0 1e-8 1e-6 1e-4}
work=$(mktemp -d)
printf "scene\tstep_tolerance\tsteps\tcg_iterations\tper_step\tquantity_1\tquantity_2\tquantity_3\tcpu_s\twall_s\n"
run() { # name tolerance prm overrides...
  local name=$1 t=$2 prm=$3; shift 3
  local args=() o out="$work/$name-$t"
  for o in "$@"; do args+=(--set "$o"); done
  /usr/bin/time -f "%U %S %e" -o "$out.time" "$bin" "$prm" "${args[@]}" \
    --set "Mass matrix/Step tolerance=$t" --set "Output/Interval=0" \
    --set "Output directory=$out" > "$out.log" 2>&1
  /usr/bin/python3 - "$out" "$name" "$t" <<'PY'
import json, sys
out, name, t = sys.argv[1:]
u, s, e = open(out + ".time").read().split()[-3:]
j = json.load(open(out + "/summary.json"))
if name == "throughput":
    rows = [l.split() for l in open(out + "/statistics.txt")
            if l.strip() and not l.startswith("#")]
    q = ["kinetic %s" % rows[-1][3], "strain %s" % rows[-1][4],
         "L %.9e" % j["angular_momentum_final"]]
else:
    err = j["errors"]
    q = ["u_L2 %.9e" % err["displacement_L2"],
         "v_L2_rms %.9e" % err["velocity_L2_rms_over_time"],
         "stress_L2 %.9e" % err["stress_L2"]]
print("\t".join([name, t, str(j["steps"]), str(j["cg_iterations"]),
                 "%.1f" % (j["cg_iterations"] / j["steps"])] + q +
                ["%.2f" % (float(u) + float(s)), e]), flush=True)
PY
}
for t in $tolerances; do
  run throughput "$t" prm/benchmark_throughput.prm \
    "Basis/Type=powell-sabin" "Mass matrix/Type=automatic" \
    "Time/End time=4e-4"
done
for t in $tolerances; do
  run "bar 64x4" "$t" prm/vibrating_bar_large.prm \
    "Mesh/Blocks x=64" "Mesh/Blocks y=4" "Particles/Per block x=4" \
    "Particles/Per block y=4" "Time/End time=5" \
    "Mass matrix/Type=automatic" "Mass matrix/Direct solver size=0"
done
for t in $tolerances; do
  run "large bar" "$t" prm/vibrating_bar_large.prm \
    "Mass matrix/Direct solver size=0"
done
rm -rf "$work"
