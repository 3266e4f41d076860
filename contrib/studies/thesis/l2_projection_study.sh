#!/bin/bash
# L2 projection of sin(pi x) sin(pi y) on the unit square, diagonal meshes:
# Powell-Sabin with 2, 4, 8, 16 blocks and P1 with 4, 8, 16, 32 blocks, with
# the consistent and the lumped mass matrix (thesis Tables 3.1 and 3.2).
#
#   contrib/studies/thesis/l2_projection_study.sh [build directory] [output .tsv]
#
# Builds the targets l2_projection_driver (and p1_reference for the
# independent P1 check) in the build directory (default: build/, as made by
# contrib/psmpm.sh). Wall time is that of L2Projection::run without VTU
# output, best of three runs.
set -euo pipefail
build=${1:-$(dirname "$0")/../../../build}
cmake --build "$build" --target l2_projection_driver p1_reference -- -j2 >/dev/null
table=${2:-$(dirname "$0")/../../../doc/l2_projection_study.tsv}
driver=$build/benchmarks/l2_projection_driver

run() { # basis mass blocks -> one line of the driver (best wall time of 3)
  local best=""
  for i in 1 2 3; do
    line=$("$driver" "$1" diagonal "$3" - "$2")
    t=$(echo "$line" | cut -f6)
    if [ -z "$best" ] || awk "BEGIN{exit !($t < $(echo "$best" | cut -f6))}"; then
      best=$line
    fi
  done
  echo "$best"
}

{
  printf "basis\tmass\tblocks\tn_vertices_per_side\tn_dofs\tL2_error\trate\twall_time_s\n"
  for mass in consistent lumped; do
    for basis in powell-sabin linear; do
      if [ "$basis" = powell-sabin ]; then list="2 4 8 16"; else list="4 8 16 32"; fi
      previous=""
      for b in $list; do
        line=$(run "$basis" "$mass" "$b")
        e=$(echo "$line" | cut -f4)
        if [ -z "$previous" ]; then rate="-"; else
          rate=$(awk "BEGIN{printf \"%.2f\", log($previous/$e)/log(2)}"); fi
        previous=$e
        echo "$line" | awk -v basis="$basis" -v mass="$mass" -v rate="$rate" \
          'BEGIN{FS=OFS="\t"} {print basis, mass, $1, $2, $3, $4, rate, $6}'
      done
    done
  done
} > "$table"
cat "$table"
