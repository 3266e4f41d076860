#!/usr/bin/env bash
# Direct solver against CG on small mass systems (reports, never fails):
# each row runs one scene twice, side by side, with the direct solver
# forced (any size, so that rows above the default Direct solver size are
# measured too) and with "Mass matrix/Direct solver size=0" (Jacobi-CG);
# prints CPU (user + sys) and wall seconds of each run and the final
# displacement error where the scene has a reference. doc/performance.md,
# "Small systems".
#   contrib/benchmarks/direct_solver_benchmark.sh [build/psmpm]
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=${1:-build/psmpm}
printf "%-58s %6s %22s %22s %s\n" scene n_dofs "direct: CPU / wall s" "CG: CPU / wall s" "E_u direct / CG"
row() { # label prm [--set ...]
  local label=$1 prm=$2 line="" dofs="" errors=""
  shift 2
  for size in 100000 0; do
    local dir
    dir=$(mktemp -d)
    /usr/bin/time -f "%U %S %e" -o "$dir.time" "$bin" "$prm" "$@" \
      --set "Output directory=$dir" --set "Output/Interval=0" \
      --set "Mass matrix/Direct solver size=$size" > /dev/null
    read -r u s w < <(tail -1 "$dir.time")
    line+=$(printf "%22s" "$(echo "$u $s $w" | awk '{printf "%.2f / %.2f", $1 + $2, $3}')")
    dofs=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['n_dofs'])" "$dir/summary.json")
    errors+=$(/usr/bin/python3 -c "import json,sys; e=json.load(open(sys.argv[1])).get('errors',{}); print('%.12e ' % e['displacement_L2'] if 'displacement_L2' in e else '- ')" "$dir/summary.json")
    rm -rf "$dir" "$dir.time"
  done
  printf "%-58s %6s %s %s\n" "$label" "$dofs" "$line" "$errors"
}
row "vibrating_bar_large (PS consistent, 35,000 steps)" prm/vibrating_bar_large.prm
for bx in 16 32 64; do
  row "vibrating_bar_large, $bx blocks, to t = 1" prm/vibrating_bar_large.prm \
    --set "Mesh/Blocks x=$bx" --set "Time/End time=1"
done
row "two_disks (P1 ghost penalty), to t = 0.5" prm/two_disks.prm --set "Time/End time=0.5"
row "column_collapse (P1 ghost penalty, floor beyond the column)" prm/column_collapse.prm
row "free_vibrating_bar (P1 ghost penalty, 31 x 4 blocks, free)" prm/free_vibrating_bar.prm \
  --set "Basis/Type=linear"
row "vibrating_bar_small_ps (PS consistent, 2,000 steps)" prm/vibrating_bar_small_ps.prm
