#!/usr/bin/env bash
# Compare two psmpm executables value by value: every scene of prm/ run
# short by both (same overrides), statistics.txt compared entry by entry
# except the wall time. Prints one line per scene: number of rows and of
# differing values (0 = bit-identical results). Reports, never fails.
#   contrib/tools/compare_runs.sh OLD_BINARY NEW_BINARY
set -uo pipefail
cd "$(dirname "$0")/../.."
old=$1; new=$2
work=$(mktemp -d)
run() { # name prm overrides...
  local name=$1 prm=$2; shift 2
  local args=() o
  [ -n "$prm" ] && args+=("$prm") # empty: the embedded default scene
  for o in "$@"; do args+=(--set "$o"); done
  for which in old new; do
    local bin=$old; [ "$which" = new ] && bin=$new
    "$bin" "${args[@]}" --set "Output directory=$work/$which-$name" \
      > "$work/$which-$name.log" 2>&1
  done
  /usr/bin/python3 - "$work" "$name" <<'PY'
import re, sys
work, name = sys.argv[1:]
def load(which):
    try:
        lines = open(f"{work}/{which}-{name}/statistics.txt").read().split("\n")
    except OSError:
        return None
    cols = [re.sub(r"^# \d+: ", "", l) for l in lines if l.startswith("#")]
    rows = [l.split() for l in lines if l and not l.startswith("#")]
    return cols, rows
a, b = load("old"), load("new")
if a is None or b is None:
    print(f"{name}\tno statistics"); sys.exit()
differing = [c for x, y in zip(a[1], b[1])
             for i, c in enumerate(a[0])
             if c != "wall_time" and c in b[0] and x[i] != y[b[0].index(c)]]
columns = sorted(set(differing))
print(f"{name}\trows {len(a[1])} {len(b[1])}\tdiffering values {len(differing)}"
      + (f"\t({', '.join(columns)})" if columns else ""))
PY
}
p=prm
run default_scene ""
run ps_bar $p/vibrating_bar_small_ps.prm "Time/End time=0.002"
run soil_small $p/soil_column_small.prm "Time/End time=0.02"
run soil_large $p/soil_column_large.prm "Time/End time=0.005"
run bar_large $p/vibrating_bar_large.prm "Time/End time=0.05"
run spreading $p/spreading_block.prm "Time/End time=0.1"
run stiff $p/stiff_column.prm "Time/End time=0.002"
run incompressible $p/incompressible_column.prm "Time/End time=0.01"
run sliver $p/sliver_mesh_bar.prm "Time/End time=0.002"
for m in consistent lumped extrapolate; do
  run "column_$m" $p/soil_column_large.prm "Time/End time=0.02" \
    "Mass matrix/Type=$m" "Mesh/Blocks y=16"
done
# The soil models (Mohr-Coulomb, Drucker-Prager: the paired returns).
run biaxial $p/biaxial_compression.prm "Time/End time=0.05"
run column_collapse $p/granular_column_collapse.prm "Time/End time=0.01"
run footing $p/strip_footing.prm "Time/End time=0.1"
run footing_body $p/strip_footing_body.prm "Time/End time=0.1"
run cut $p/vertical_cut.prm "Time/End time=0.2"
run slope $p/frictional_slope.prm "Time/End time=0.2"
run column_collapse_dp $p/granular_column_collapse.prm "Time/End time=0.01" \
  "Material/Model=drucker-prager"
rm -rf "$work"
