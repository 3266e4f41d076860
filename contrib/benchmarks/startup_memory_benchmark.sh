#!/usr/bin/env bash
# Reports (never fails on numbers) three things of doc/performance.md, one
# run after the other, CPU (user + sys) beside wall seconds:
# 1. start-up: a program that only links libdeal.ii and returns, and
#    `psmpm --help`;
# 2. the thesis bar, P1 on 32 blocks against Powell-Sabin on 5, 6 and 8
#    blocks: E_u, whole-process CPU, CPU of the time loop
#    (summary.json cpu_time_loop_s), wall;
# 3. peak resident memory of the throughput bar (mesh fixed) with 4, 8 and
#    16 particles per block side, P1 lumped and the Powell-Sabin default.
#   contrib/benchmarks/startup_memory_benchmark.sh [path/to/psmpm]
set -euo pipefail
cd "$(dirname "$0")/../.."
psmpm=$(realpath "${1:-build/psmpm}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
field() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$1" "$2"; }

echo "## start-up (user s, sys s, wall s)"
echo 'int main() { return 0; }' >"$tmp/empty.cc"
g++ "$tmp/empty.cc" -o "$tmp/dealii_only" -Wl,--no-as-needed \
  /usr/lib/x86_64-linux-gnu/libdeal.ii.so
for i in 1 2; do /usr/bin/time -f "libdeal.ii only: %U %S %e" "$tmp/dealii_only"; done
for i in 1 2; do /usr/bin/time -f "psmpm --help: %U %S %e" "$psmpm" --help >/dev/null; done

echo "## thesis bar: run | E_u | cpu_time_s | cpu_time_loop_s | wall_time_s"
for run in "vibrating_bar_small 32" "vibrating_bar_small_ps 5" \
           "vibrating_bar_small_ps 6" "vibrating_bar_small_ps 8"; do
  set -- $run
  "$psmpm" "prm/$1.prm" --set "Mesh/Blocks x=$2" --set "Output/Interval=0" \
    --set "Output directory=$tmp/bar" >/dev/null
  s="$tmp/bar/summary.json"
  echo "$1 $2 | $(field "$s" "'%.3e' % d['errors']['displacement_L2']") | $(field "$s" "d['cpu_time_s']") | $(field "$s" "d['cpu_time_loop_s']") | $(field "$s" "d['wall_time_s']")"
done

echo "## throughput bar: basis mass | particles | max RSS kB | user s | sys s | wall s"
for run in "linear lumped" "powell-sabin automatic"; do
  set -- $run
  for ppb in 4 8 16; do
    /usr/bin/time -f "%M %U %S %e" -o "$tmp/mem.time" "$psmpm" \
      prm/benchmark_throughput.prm --set "Basis/Type=$1" \
      --set "Mass matrix/Type=$2" --set "Particles/Per block x=$ppb" \
      --set "Particles/Per block y=$ppb" --set "Time/End time=5e-5" \
      --set "Output directory=$tmp/mem" >/dev/null
    echo "$1 $2 | $(field "$tmp/mem/summary.json" "d['n_particles']") | $(cat "$tmp/mem.time")"
  done
done
