#!/usr/bin/env bash
# The thesis' small-deformation bar with Powell-Sabin (Table 4.3,
# prm/vibrating_bar_small_ps.prm: 56 particles per element, consistent mass)
# with particle quadrature and with the Taylor least squares internal force
# (Transfer/Reconstruction = taylor least squares, Fields = stress), 1 to
# 16 blocks, one run after the other: E_u at t = 0.02, the rate, and the CPU
# (user + sys) and wall seconds of each whole run. doc/chapter.md.
#   contrib/studies/chapter/thesis_bar_tls.sh [path/to/psmpm]
set -euo pipefail
cd "$(dirname "$0")/../../.."
psmpm=${1:-build/psmpm}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| blocks | reconstruction | E_u | rate | stress L2 | CPU s (user+sys) | wall s |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for r in particles "taylor least squares"; do
  prev=
  for n in 1 2 4 8 16; do
    out="$tmp/$n-${r%% *}"
    /usr/bin/time -f "%U %S %e" -o "$out.time" "$psmpm" \
      prm/vibrating_bar_small_ps.prm --set "Mesh/Blocks x=$n" \
      --set "Transfer/Reconstruction=$r" \
      --set "Transfer/Taylor least squares/Fields=stress" \
      --set "Output/Interval=0" --set "Output directory=$out" >/dev/null
    read -r user sys wall <"$out.time"
    /usr/bin/python3 - "$out/summary.json" "$n" "$r" "$user" "$sys" "$wall" "$prev" <<'PY' | tee "$out.row"
import json, math, sys
s = json.load(open(sys.argv[1]))
e = s["errors"]
u = e["displacement_L2"]
rate = "-" if not sys.argv[7] else "%.2f" % math.log2(float(sys.argv[7]) / u)
print("| %s | %s | %.4e | %s | %.3e | %.2f | %.2f |" % (
    sys.argv[2], sys.argv[3], u, rate, e["stress_L2"],
    float(sys.argv[4]) + float(sys.argv[5]), float(sys.argv[6])))
PY
    prev=$(/usr/bin/python3 -c "import json;print(json.load(open('$out/summary.json'))['errors']['displacement_L2'])")
  done
done
