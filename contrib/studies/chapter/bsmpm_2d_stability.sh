#!/bin/bash
# Stable time step of 2D BSMPM (Basis/Type = bspline, Mesh/Type =
# cartesian), doc/chapter.md "BSMPM in 2D": the automatic time step
# dt = C f h_min / c_p at Courant numbers C from 0.8 to 2, quadratic
# B-splines, lumped, consistent and ghost penalty mass, on
#  box:  an 8 x 2 body filling an 8 x 2 mesh with roller walls, velocity
#        in both directions (the stability limit proper), and
#  free: the same body free inside a 12 x 4 mesh (cells empty as it moves).
# Prints status, steps, time step and the reason of an unstable stop.
#
#   bash contrib/studies/chapter/bsmpm_2d_stability.sh [build/psmpm]
set -eu
psmpm=$(realpath "${1:-build/psmpm}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
scene() { # $1 = box|free, $2 = mass, $3 = Courant number
  if [ "$1" = box ]; then
    geometry="set Length = 8
  set Height = 2"; blocks="set Blocks x = 8
  set Blocks y = 2"; region=""
    velocity="0.1*sin(pi*x/8); 0.05*sin(pi*y/2)*cos(pi*x/8)"
    fixed="set Fixed x = left, right
  set Fixed y = bottom, top"
  else
    geometry="set Length = 12
  set Height = 4"; blocks="set Blocks x = 12
  set Blocks y = 4"; region="set Region = 2, 1, 10, 3"
    velocity="0.1*sin(pi*(x-2)/8); 0.05*cos(pi*(x-2)/8)"
    fixed="set Fixed x =
  set Fixed y ="
  fi
  cat <<PRM
set Output directory = out
subsection Geometry
  $geometry
end
subsection Mesh
  set Type = cartesian
  $blocks
end
subsection Basis
  set Type = bspline
end
subsection Material
  set Density = 1
  set Young's modulus = 100
  set Poisson's ratio = 0.3
end
subsection Particles
  set Per block x = 3
  set Per block y = 3
  $region
end
subsection Initial conditions
  set Velocity = $velocity
end
subsection Boundary conditions
  $fixed
end
subsection Time
  set End time = 10
  set Time step = 0
  set Courant number = $3
  set Check stability bound = false
end
subsection Mass matrix
  set Type = $2
end
subsection Output
  set Interval = 0
end
PRM
}
for s in box free; do
  for m in lumped consistent "ghost penalty"; do
    for c in 0.8 0.9 1.0 1.1 1.2 1.4 1.7 2.0; do
      scene $s $m $c > scene.prm
      "$psmpm" scene.prm > /dev/null 2>&1 || true
      /usr/bin/python3 -c "
import json; s = json.load(open('out/summary.json'))
print('$s $m C = $c:', s['status'], s['steps'], 'steps, dt = %.3g' % s['time_step'], s.get('reason', '')[:70])"
    done
  done
done
