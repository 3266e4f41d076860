#!/bin/bash
# The defaults' check: every scene of the stability suite with the
# defaults (Mass matrix/Type = automatic, Transfer/Scheme = automatic,
# automatic time step recomputed every step: Time/Time step = 0), both
# bases. One markdown table: status, steps, conservation, error against
# the scene's reference, CPU (user + sys) and wall seconds.
#
#   contrib/studies/stability/defaults_suite.sh [work dir] [--set ... passed to every run]
# (BASES="linear" runs one basis only, SKIP_CANTILEVER=1 skips the cantilever)
set -uo pipefail
here=$(cd "$(dirname "$0")/../../.." && pwd)
work=${1:-$(mktemp -d /tmp/psmpm-defaults.XXXXXX)}
[ $# -gt 0 ] && shift
bin=${PSMPM:-$here/build/psmpm}
mkdir -p "$work"
echo "| scene | basis | status | steps | dt min..max | dL/L | angle | displacement L2 | period error | mean deflection error | CPU s | wall s |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
scene() { # name prm [--set ...]
  local name=$1 prm=$2; shift 2
  for basis in ${BASES:-linear powell-sabin}; do
    local out="$work/${name}_${basis}"
    /usr/bin/time -f "%U %S" -o "$out.time" "$bin" "$here/prm/$prm" \
      --set "Output directory=$out" --set "Output/Interval=0" \
      --set "Basis/Type=$basis" --set "Mass matrix/Type=automatic" \
      --set "Transfer/Scheme=automatic" --set "Time/Time step=0" \
      "$@" "${extra[@]}" > "$out.log" 2>&1
    /usr/bin/python3 - "$out" "$name" "$basis" <<'PY'
import json, sys
out, name, basis = sys.argv[1:]
try:
    j = json.load(open(out + "/summary.json"))
except Exception:
    print(f"| {name} | {basis} | no summary (see {out}.log) |||||||||")
    sys.exit()
u, s = map(float, open(out + ".time").read().split()[-2:])
f = lambda k, fmt: format(j[k], fmt) if k in j else "-"
err = j.get("errors", {}).get("displacement_L2")
osc = j.get("oscillation", {})
g = lambda k: format(osc[k], "+.4f") if k in osc else "-"
st = j["status"] + ("" if j["status"] == "completed" else f" ({j.get('reason', '')})")
print(f"| {name} | {basis} | {st} | {j['steps']} | "
      f"{j.get('time_step_min', 0):.2e}..{j.get('time_step_max', 0):.2e} | "
      f"{f('angular_momentum_relative_change', '+.4f')} | {f('rotation_angle_final', '.4f')} | "
      f"{format(err, '.3e') if err is not None else '-'} | {g('period_error')} | {g('tip_mean_deflection_error')} | "
      f"{u + s:.2f} | {j.get('wall_time_s', 0):.2f} |")
PY
  done
}
extra=("$@")
scene rotation rotating_block.prm
scene rotation_stiff rotating_block.prm --set "Material/Young's modulus=1e9"
scene rotation_nu049 rotating_block.prm --set "Material/Poisson's ratio=0.49"
scene slumping_block spreading_block.prm
scene falling_block falling_block.prm
scene thesis_bar vibrating_bar_small_ps.prm --set "Mesh/Blocks x=4"
scene soil_column_2x16 soil_column_small.prm --set "Mesh/Blocks x=2" --set "Mesh/Blocks y=16"
scene stiff_column stiff_column.prm
scene incompressible_column incompressible_column.prm
[ -n "${SKIP_CANTILEVER:-}" ] || scene cantilever cantilever.prm
