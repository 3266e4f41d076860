#!/usr/bin/env bash
# Per-step overhead of small systems, two builds side by side (reports,
# never fails): each scene runs with binary A, then with binary B, output
# off; prints user, sys and wall seconds of each run, the number of
# getrusage system calls (strace -c, if strace is installed; a second,
# uncounted-time run) and whether the statistics agree (every column but
# wall time, md5). doc/performance.md, "Per-step overhead".
#   contrib/benchmarks/step_overhead_benchmark.sh OLD/psmpm NEW/psmpm
set -euo pipefail
cd "$(dirname "$0")/../.."
a=$1
b=$2
printf "%-44s %-4s %7s %7s %7s %10s %s\n" scene run user_s sys_s wall_s getrusage statistics_md5
row() { # label prm [--set ...]
  local label=$1 prm=$2
  shift 2
  for tag in A B; do
    local bin=$a dir calls="-"
    [ $tag = B ] && bin=$b
    dir=$(mktemp -d)
    /usr/bin/time -f "%U %S %e" -o "$dir.time" "$bin" "$prm" "$@" \
      --set "Output directory=$dir" --set "Output/Interval=0" > /dev/null
    read -r u s w < <(tail -1 "$dir.time")
    local md5
    md5=$(grep -v '^#' "$dir/statistics.txt" | awk '{ $NF=""; print }' | md5sum | cut -c1-10)
    if command -v strace > /dev/null; then
      calls=$(strace -f -c -e trace=getrusage -o "$dir.strace" "$bin" "$prm" "$@" \
        --set "Output directory=$dir/s" --set "Output/Interval=0" > /dev/null 2>&1 \
        && awk '$NF == "getrusage" { print $4 }' "$dir.strace")
      calls=${calls:-0}
    fi
    printf "%-44s %-4s %7s %7s %7s %10s %s\n" "$label" "$tag" "$u" "$s" "$w" "$calls" "$md5"
    rm -rf "$dir" "$dir.time" "$dir.strace"
  done
}
row "vibrating_bar_large (PS consistent, 35,000)" prm/vibrating_bar_large.prm
row "vibrating_bar_small_ps (PS consistent)" prm/vibrating_bar_small_ps.prm
row "rotating_block (P1 lumped)" prm/rotating_block.prm
row "two_disks (P1 ghost penalty, to t = 0.5)" prm/two_disks.prm --set "Time/End time=0.5"
