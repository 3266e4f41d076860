#!/bin/bash
# Error against CPU time with the defaults (Mass matrix/Type and
# Transfer/Scheme = automatic, automatic time step), both bases:
# * cantilever under self-weight (prm/cantilever.prm) with k = 2..6 blocks
#   through the depth of the beam: error = max(|period error|, |mean
#   deflection error|) against the plane-strain Q2 FE reference;
# * free rotating block (prm/rotating_block.prm) on 8 x 8 and 16 x 16
#   meshes: error = |angular momentum change| and |angle / (pi/2) - 1|.
# CPU = user + sys seconds (/usr/bin/time): robust to other load.
# Writes runs.tsv and error_vs_cpu.png into the work directory (default a
# new one under /tmp); copy the png into doc/images/ by hand.
#
#   contrib/studies/thesis/error_vs_cpu.sh [work dir] [max blocks through the depth]
set -euo pipefail
here=$(cd "$(dirname "$0")/../../.." && pwd)
work=${1:-$(mktemp -d /tmp/psmpm-error-cpu.XXXXXX)}
kmax=${2:-6}
bin=${PSMPM:-$here/build/psmpm}
mkdir -p "$work"
tsv="$work/runs.tsv"
echo -e "scene\tbasis\tk\tstatus\terror\tperiod_error\tmean_error\tcpu_s" > "$tsv"
record() { # scene basis k out
  /usr/bin/python3 - "$@" >> "$tsv" <<'PY'
import json, sys
scene, basis, k, out = sys.argv[1:]
u, s = map(float, open(out + ".time").read().split()[-2:])
try:
    j = json.load(open(out + "/summary.json"))
except Exception:
    print(f"{scene}\t{basis}\t{k}\tno-summary\tnan\tnan\tnan\t{u+s:.2f}"); sys.exit()
if scene == "cantilever":
    o = j.get("oscillation", {})
    p, m = o.get("period_error", float("nan")), o.get("tip_mean_deflection_error", float("nan"))
    e = max(abs(p), abs(m))
else:
    p = j.get("angular_momentum_relative_change", float("nan"))
    m = j.get("rotation_angle_final", float("nan")) / 1.5707963267948966 - 1
    e = max(abs(p), abs(m))
print(f"{scene}\t{basis}\t{k}\t{j['status']}\t{e:.4e}\t{p:+.4e}\t{m:+.4e}\t{u+s:.2f}")
PY
}
defaults=(--set "Mass matrix/Type=automatic" --set "Transfer/Scheme=automatic"
          --set "Time/Time step=0" --set "Output/Interval=0")
for basis in powell-sabin linear; do
  for k in $(seq 2 "$kmax"); do
    h=$(/usr/bin/python3 -c "print(0.5/$k)")
    y0=$(/usr/bin/python3 -c "h=0.5/$k; print(round(0.25/h)*h)")
    out="$work/cantilever_${basis}_$k"
    /usr/bin/time -f "%U %S" -o "$out.time" "$bin" "$here/prm/cantilever.prm" \
      "${defaults[@]}" --set "Output directory=$out" --set "Basis/Type=$basis" \
      --set "Mesh/Blocks x=$((9 * k))" --set "Mesh/Blocks y=$((2 * k))" \
      --set "Particles/Region=0, $y0, 4, $(/usr/bin/python3 -c "print($y0+0.5)")" \
      --set "Output/Tracked point=4, $(/usr/bin/python3 -c "print($y0+0.25)")" \
      > "$out.log" 2>&1 || true
    record cantilever "$basis" "$k" "$out"
  done
  for n in 8 16; do
    out="$work/rotation_${basis}_$n"
    /usr/bin/time -f "%U %S" -o "$out.time" "$bin" "$here/prm/rotating_block.prm" \
      "${defaults[@]}" --set "Output directory=$out" --set "Basis/Type=$basis" \
      --set "Mesh/Blocks x=$n" --set "Mesh/Blocks y=$n" > "$out.log" 2>&1 || true
    record rotation "$basis" "$n" "$out"
  done
done
column -t "$tsv"
/usr/bin/python3 - "$tsv" "$work/error_vs_cpu.png" <<'PY'
import sys, csv
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
for ax, scene, title in zip(axes, ["cantilever", "rotation"],
                            ["cantilever: max(|period|, |mean deflection|) error",
                             "rotating block: max(|dL/L|, |angle error|)"]):
    for basis, mark in [("powell-sabin", "o-"), ("linear", "s--")]:
        r = [x for x in rows if x["scene"] == scene and x["basis"] == basis
             and x["status"] == "completed"]
        ax.loglog([float(x["cpu_s"]) for x in r], [float(x["error"]) for x in r],
                  mark, label=basis)
        for x in r:
            ax.annotate(x["k"], (float(x["cpu_s"]), float(x["error"])), fontsize=8)
    if scene == "cantilever":
        ax.axhline(0.01, color="gray", lw=0.8)
    ax.set_xlabel("CPU seconds (user + sys)")
    ax.set_ylabel("relative error")
    ax.set_title(title, fontsize=9)
    ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
print("plot:", sys.argv[2])
PY
