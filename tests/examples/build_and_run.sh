#!/usr/bin/env bash
# Install psmpm from a build tree, build an out-of-tree example against the
# installation and run it on a scene. Passes only if the run exits 0 and
# its summary.json says "status": "completed", and, if a CHECK command is
# given, that command passes on the run's results:
#   build_and_run.sh CMAKE PSMPM_BUILD_DIR EXAMPLE_SOURCE_DIR SCENE WORK_DIR \
#     [CHECK ARGS...]
# runs CHECK ARGS... EXECUTABLE SCENE_FILE OUTPUT_DIRECTORY last.
# The executable is the example's project name (its directory name).
set -euo pipefail

cmake=$1 psmpm_build=$2 source=$3 scene=$4 work=$5
name=$(basename "$source")
prefix=$work/prefix

rm -rf "$work"
mkdir -p "$work/run"

echo "== install psmpm into $prefix"
"$cmake" --install "$psmpm_build" --prefix "$prefix"

# Same compiler launcher and build type as psmpm, so that ccache helps and
# deal_ii_setup_target picks the same deal.II flavour.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
echo "== configure and build $name against it"
"$cmake" -S "$source" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}"
"$cmake" --build "$work/build" -j2

# Open MPI refuses to start as root unless told that this is intended.
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

echo "== run $name $scene"
cd "$work/run"
status=0
"$work/build/$name" "$source/$scene" || status=$?
if [ "$status" -ne 0 ]; then
  echo "FAIL: $name exited with $status" >&2
  exit 1
fi

# The scene's "Output directory" is relative to the working directory.
summary=$(find "$work/run" -name summary.json | head -n 1)
if [ -z "$summary" ]; then
  echo "FAIL: no summary.json under $work/run" >&2
  exit 1
fi
if ! grep -Eq '"status"[[:space:]]*:[[:space:]]*"completed"' "$summary"; then
  echo "FAIL: $summary does not report \"status\": \"completed\":" >&2
  cat "$summary" >&2
  exit 1
fi
echo "OK: $summary reports completed"

if [ $# -gt 5 ]; then
  shift 5
  echo "== check $*"
  "$@" "$work/build/$name" "$source/$scene" "$(dirname "$summary")"
fi
