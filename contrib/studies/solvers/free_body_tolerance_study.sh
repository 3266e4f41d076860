#!/usr/bin/env bash
# Free bodies against Mass matrix/Free body step tolerance: CG iterations
# and the particles' momentum and angular momentum changes.
# * block: prm/rotating_block.prm spinning and translating (velocity
#   0.3 - (y - 0.5); 0.2 + x - 0.5), P1 with the ghost penalty, MUSL,
#   every system through CG (Direct solver size = 0), 0.1 s;
# * free bar: the 320,000-particle bar of prm/benchmark_throughput.prm
#   without its fixed boundaries, P1 default (ghost penalty, MUSL),
#   40 steps; one core (taskset -c 0).
# Changes relative to |initial| (momentum from summary.json's
# momentum_*_initial/final, angular momentum its
# angular_momentum_relative_change). CPU = user + sys. Reports, never
# fails. Applying contrib/experiments/no_rigid_mode_correction.patch
# gives the same rows without the rigid-mode correction.
#   contrib/studies/solvers/free_body_tolerance_study.sh [psmpm binary] [tolerances...]
set -uo pipefail
cd "$(dirname "$0")/../../.."
bin=${1:-build/psmpm}
shift || true
tolerances=${*:-0 1e-8 1e-6}
work=$(mktemp -d)
printf "scene\tfree_step_tolerance\tcg_iterations\tmomentum_change\tangular_momentum_change\tsolve_s\tcpu_s\twall_s\n"
run() { # name tolerance prm overrides...
  local name=$1 t=$2 prm=$3; shift 3
  local args=() o out="$work/$name-$t"
  for o in "$@"; do args+=(--set "$o"); done
  /usr/bin/time -f "%U %S %e" -o "$out.time" taskset -c 0 "$bin" "$prm" \
    "${args[@]}" --set "Mass matrix/Free body step tolerance=$t" \
    --set "Output/Interval=0" --set "Output directory=$out" > "$out.log" 2>&1 ||
    { echo "$name $t failed"; tail -3 "$out.log"; return; }
  /usr/bin/python3 - "$out" "$name" "$t" <<'PY'
import json, math, sys
out, name, t = sys.argv[1:]
u, s, e = open(out + ".time").read().split()[-3:]
j = json.load(open(out + "/summary.json"))
p0 = [j["momentum_%s_initial" % c] for c in "xy"]
p1 = [j["momentum_%s_final" % c] for c in "xy"]
dp = math.hypot(p1[0] - p0[0], p1[1] - p0[1]) / math.hypot(*p0)
print("%s\t%s\t%d\t%.1e\t%.1e\t%.2f\t%.2f\t%s" % (
    name, t, j["cg_iterations"], dp,
    abs(j["angular_momentum_relative_change"]),
    j["timers_s"]["solve"], float(u) + float(s), e))
PY
}
for t in $tolerances; do
  run block "$t" prm/rotating_block.prm "Basis/Type=linear" \
    "Mass matrix/Type=ghost penalty" "Transfer/Scheme=musl" \
    "Mass matrix/Direct solver size=0" \
    "Initial conditions/Velocity=0.3 - (y - 0.5); 0.2 + x - 0.5" \
    "Time/End time=0.1"
done
for t in $tolerances; do
  run free_bar "$t" prm/benchmark_throughput.prm "Basis/Type=linear" \
    "Mass matrix/Type=automatic" "Transfer/Scheme=automatic" \
    "Boundary conditions/Fixed x=" "Boundary conditions/Fixed y="
done
rm -rf "$work"
