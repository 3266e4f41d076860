#!/usr/bin/env bash
# P1 vibrating bar refinement series (thesis Table 4.2) -> doc/data/.
set -euo pipefail
cd "$(dirname "$0")/../../.."
/usr/bin/python3 contrib/tools/run_series.py --prm prm/vibrating_bar_small.prm \
  --vary "Mesh/Blocks x=4,8,16,32" --out doc/data/vibrating_bar_p1.tsv
