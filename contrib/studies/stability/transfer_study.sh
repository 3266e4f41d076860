#!/bin/bash
# Every basis x mass matrix x transfer on one scene, as a markdown table:
# status, steps, relative change of angular momentum, final mean rotation
# angle, displacement error (if the scene has a reference), period and
# mean-deflection errors (oscillating references: the cantilever), CPU
# seconds (user + sys, /usr/bin/time) and wall seconds.
#
#   contrib/studies/stability/transfer_study.sh [scene.prm] [work dir] [--set ... passed on]
#
# Default scene: prm/rotating_block.prm (a free block turning a quarter
# turn; the angle to reach is pi/2 = 1.5708). Runs go to the work dir
# (default: a new directory under /tmp), never into the repository.
set -euo pipefail
here=$(cd "$(dirname "$0")/../../.." && pwd)
scene=${1:-$here/prm/rotating_block.prm}
work=${2:-$(mktemp -d /tmp/psmpm-transfer-study.XXXXXX)}
shift $(( $# > 2 ? 2 : $# )) || true
bin=${PSMPM:-$here/build/psmpm}
mkdir -p "$work"
echo "scene: $scene, runs in: $work"
echo
echo "| basis | mass | transfer | status | steps | dL/L | angle | displacement L2 | period error | mean deflection error | CPU s | wall s |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for basis in linear powell-sabin; do
  for mass in lumped "partially lumped" consistent; do
    for transfer in musl "apic:automatic" "apic:none"; do
      scheme=${transfer%%:*}
      affine=${transfer#*:}
      [ "$affine" = "$transfer" ] && affine=automatic
      out="$work/${basis}_${mass// /_}_${scheme}_${affine// /_}"
      /usr/bin/time -f "%U %S" -o "$out.time" "$bin" "$scene" \
        --set "Output directory=$out" --set "Output/Interval=0" \
        --set "Basis/Type=$basis" --set "Mass matrix/Type=$mass" \
        --set "Transfer/Scheme=$scheme" --set "Transfer/Affine matrix=$affine" \
        "$@" > "$out.log" 2>&1 || true
      /usr/bin/python3 - "$out" "$basis" "$mass" "$transfer" <<'PY'
import json, sys
out, basis, mass, transfer = sys.argv[1:]
try:
    j = json.load(open(out + "/summary.json"))
except Exception:
    print(f"| {basis} | {mass} | {transfer} | no summary (see {out}.log) | | | | | | | | |")
    sys.exit()
u, s = map(float, open(out + ".time").read().split()[-2:])
f = lambda k, fmt: format(j[k], fmt) if k in j else "-"
err = j.get("errors", {}).get("displacement_L2")
osc = j.get("oscillation", {})
g = lambda k: format(osc[k], "+.4f") if k in osc else "-"
print(f"| {basis} | {mass} | {transfer} | {j['status']} | {j['steps']} | "
      f"{f('angular_momentum_relative_change', '+.4f')} | {f('rotation_angle_final', '.4f')} | "
      f"{format(err, '.3e') if err is not None else '-'} | {g('period_error')} | {g('tip_mean_deflection_error')} | "
      f"{u + s:.2f} | {j.get('wall_time_s', 0):.2f} |")
PY
    done
  done
done
