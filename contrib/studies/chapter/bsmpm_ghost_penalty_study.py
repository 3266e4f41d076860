#!/usr/bin/python3
"""Ghost penalty mass for 2D BSMPM (Basis/Type = bspline, Mesh/Type =
cartesian), doc/chapter.md "BSMPM in 2D": is it stable where consistent
mass fails (nearly empty cells) and as accurate where the mesh is full?

  /usr/bin/python3 contrib/studies/chapter/bsmpm_ghost_penalty_study.py [build/psmpm]
  (PSMPM_STUDY_PARTS=free,sweep,p3,bar,column,collapse,1d to pick parts)

 free:     the free body of contrib/studies/chapter/bsmpm_2d_stability.sh (8 x 2 body in a
           12 x 4 mesh, velocity in both directions, End time 10) at
           Courant numbers 0.5 to 2.0, lumped, consistent and ghost penalty
           (Stabilization 1), quadratic B-splines;
 sweep:    the ghost penalty's Stabilization at Courant 0.9 and 1.4;
 p3:       the free body with cubic B-splines (consistent, ghost penalty);
 bar:      the thesis bar, 8 (and 16) rectangles, p = 2 and 3;
 column:   the soil column (prm/soil_column_small.prm) on 1 x 8 cells;
 collapse: prm/column_collapse.prm on 24 x 10 rectangles (no test uses it);
 1d:       1D B-splines: a free bar of 8 cells inside 12 (Courant 0.5 to
           1.0) and the filled chapter and vibrating bars.

Per run: status, steps, energy rise (largest rise of kinetic + strain +
gravitational energy above its initial value over the largest energy),
largest change of the momentum vector (over the largest |momentum| seen;
meaningful for the free body only, which has neither gravity nor walls),
treated DoFs (largest number with a ghost penalty block), cell crossings, errors.displacement_L2, CPU s of the process (user
+ sys, as /usr/bin/time) and wall s. One run after the other; reports,
never fails.
"""
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.path.realpath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(ROOT, "build", "psmpm"))
PARTS = os.environ.get("PSMPM_STUDY_PARTS",
                       "free,sweep,p3,bar,column,collapse,1d").split(",")

FREE = """set Output directory = {out}
subsection Geometry
  set Length = 12
  set Height = 4
end
subsection Mesh
  set Type = cartesian
  set Blocks x = 12
  set Blocks y = 4
end
subsection Basis
  set Type = bspline
  set Degree = {p}
end
subsection Material
  set Density = 1
  set Young's modulus = 100
  set Poisson's ratio = 0.3
end
subsection Particles
  set Per block x = 3
  set Per block y = 3
  set Region = 2, 1, 10, 3
end
subsection Initial conditions
  set Velocity = 0.1*sin(pi*(x-2)/8); 0.05*cos(pi*(x-2)/8)
end
subsection Boundary conditions
  set Fixed x =
  set Fixed y =
end
subsection Time
  set End time = 10
  set Time step = 0
  set Courant number = {courant}
  set Check stability bound = false
end
subsection Mass matrix
  set Type = {mass}
  set Stabilization = {gamma}
end
subsection Output
  set Interval = 0
end
"""


FREE_1D = """set Output directory = {out}
subsection Geometry
  set Dimension = 1
  set Length = 12
end
subsection Mesh
  set Blocks x = 12
end
subsection Basis
  set Type = bspline
  set Degree = 2
end
subsection Material
  set Density = 1
  set Young's modulus = 100
  set Poisson's ratio = 0
end
subsection Particles
  set Per block x = 3
  set Region = 2, 10
end
subsection Initial conditions
  set Velocity = 0.1*sin(pi*(x-2)/8)
end
subsection Boundary conditions
  set Fixed x =
end
subsection Time
  set End time = 10
  set Time step = 0
  set Courant number = {courant}
end
subsection Mass matrix
  set Type = {mass}
end
subsection Output
  set Interval = 0
end
"""


def run(args):
    out = tempfile.mkdtemp(prefix="psmpm-ghost-")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    if isinstance(args, str):
        prm = os.path.join(out, "scene.prm")
        open(prm, "w").write(args.format(out=out))
        cmd = [BIN, prm]
    else:
        cmd = [BIN] + args + ["--set", f"Output directory={out}",
                              "--set", "Output/Interval=0"]
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime -
                                                before.ru_stime)
    try:
        s = json.load(open(os.path.join(out, "summary.json")))
    except (OSError, ValueError):
        return {"status": f"exit {p.returncode}",
                "reason": p.stderr.decode()[-200:], "cpu": cpu, "wall": wall}
    cols, rows = [], []
    try:
        for line in open(os.path.join(out, "statistics.txt")):
            if line.startswith("#"):
                cols.append(line.split(":", 1)[1].strip())
            else:
                rows.append(line.split())
    except OSError:
        pass
    col = {c: i for i, c in enumerate(cols)}

    def series(name):
        if name not in col:
            return []
        return [float(r[col[name]]) for r in rows if r[col[name]] != "-"]

    k, w, g = (series("kinetic_energy"), series("strain_energy"),
               series("gravity_energy"))
    if k:
        total = [a + b + c for a, b, c in zip(k, w, g)]
        scale = max(max(a + b + abs(c) for a, b, c in zip(k, w, g)), 1e-300)
        s["energy_rise"] = max(t - total[0] for t in total) / scale
    mx, my = series("momentum_x"), series("momentum_y")
    my = my or [0.] * len(mx)  # 1D
    drift = 0
    if mx:
        scale = max(max((a * a + b * b) ** 0.5 for a, b in zip(mx, my)),
                    1e-300)
        drift = max(((a - mx[0]) ** 2 + (b - my[0]) ** 2) ** 0.5
                    for a, b in zip(mx, my)) / scale
    s["momentum_drift"] = drift
    s["treated"] = int(max(series("treated_dofs") or [0]))
    s["cpu"], s["wall"], s["exit"] = cpu, wall, p.returncode
    return s


def row(label, s):
    e = s.get("errors", {}) or {}
    eu = s.get("errors.displacement_L2", e.get("displacement_L2"))
    cells = [label, s.get("status", "?"), str(s.get("steps", "")),
             "%.3g" % s["time_step"] if "time_step" in s else "",
             "%.2e" % s["energy_rise"] if "energy_rise" in s else "",
             "%.1e" % s["momentum_drift"] if "momentum_drift" in s else "",
             str(s.get("treated", "")), str(s.get("cell_crossings", "")),
             "%.4e" % eu if isinstance(eu, float) else "",
             "%.2f" % s["cpu"], "%.2f" % s["wall"],
             (s.get("reason", "") or "")[:60]]
    print("| " + " | ".join(cells) + " |", flush=True)


def header(title):
    print(f"\n### {title}\n")
    print("| run | status | steps | dt | energy rise | momentum drift "
          "| treated DoFs | cell crossings | E_u | CPU s "
          "| wall s | reason |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|",
          flush=True)


def main():
    print(f"psmpm: {BIN}")
    courants = ["0.5", "0.8", "0.9", "1.0", "1.2", "1.4", "1.7", "2.0"]
    if "free" in PARTS:
        header("Free body, 12 x 4 mesh, p = 2")
        for mass in ["lumped", "consistent", "ghost penalty"]:
            for c in courants:
                row(f"{mass}, C = {c}",
                    run(FREE.format(out="{out}", p=2, courant=c, mass=mass,
                                    gamma=1)))
    if "sweep" in PARTS:
        header("Free body, p = 2, ghost penalty Stabilization")
        for c in ["0.9", "1.4"]:
            for gamma in ["0.01", "0.1", "1", "10"]:
                row(f"gamma = {gamma}, C = {c}",
                    run(FREE.format(out="{out}", p=2, courant=c,
                                    mass="ghost penalty", gamma=gamma)))
    if "p3" in PARTS:
        header("Free body, 12 x 4 mesh, p = 3")
        for mass in ["consistent", "ghost penalty"]:
            for c in ["0.5", "0.9", "1.0", "1.4", "2.0"]:
                row(f"{mass}, C = {c}",
                    run(FREE.format(out="{out}", p=3, courant=c, mass=mass,
                                    gamma=1)))
    if "bar" in PARTS:
        header("Thesis bar (prm/vibrating_bar_small_ps.prm), cartesian")
        for p, blocks in [(2, 8), (2, 16), (3, 8)]:
            for mass in ["consistent", "ghost penalty", "lumped"]:
                if p == 3 and mass == "lumped":
                    continue
                row(f"p = {p}, {blocks} cells, {mass}",
                    run([os.path.join(ROOT, "prm",
                                      "vibrating_bar_small_ps.prm"),
                         "--set", "Mesh/Type=cartesian",
                         "--set", "Basis/Type=bspline",
                         "--set", f"Basis/Degree={p}",
                         "--set", f"Mesh/Blocks x={blocks}",
                         "--set", f"Mass matrix/Type={mass}"]))
    if "column" in PARTS:
        header("Soil column (prm/soil_column_small.prm), cartesian")
        for blocks in [8, 16]:
            for mass in ["consistent", "ghost penalty", "lumped"]:
                row(f"1 x {blocks} cells, {mass}",
                    run([os.path.join(ROOT, "prm", "soil_column_small.prm"),
                         "--set", "Mesh/Type=cartesian",
                         "--set", "Basis/Type=bspline",
                         "--set", f"Mesh/Blocks y={blocks}",
                         "--set", f"Mass matrix/Type={mass}"]))
    if "collapse" in PARTS:
        header("Column collapse (prm/column_collapse.prm), cartesian")
        for p in [2, 3]:
            for mass in ["lumped", "consistent", "ghost penalty"]:
                if p == 3 and mass == "lumped":
                    continue
                row(f"p = {p}, {mass}",
                    run([os.path.join(ROOT, "prm", "column_collapse.prm"),
                         "--set", "Mesh/Type=cartesian",
                         "--set", "Basis/Type=bspline",
                         "--set", f"Basis/Degree={p}",
                         "--set", f"Mass matrix/Type={mass}"]))
    if "1d" in PARTS:
        header("1D free bar, 8 cells inside 12, p = 2")
        for mass in ["lumped", "consistent", "ghost penalty"]:
            for c in ["0.5", "0.8", "0.9", "1.0"]:
                row(f"{mass}, C = {c}",
                    run(FREE_1D.format(out="{out}", courant=c, mass=mass)))
        header("1D bars, filled mesh, p = 2")
        for prm in ["chapter_bar_1d.prm", "vibrating_bar_1d.prm"]:
            for mass in ["consistent", "ghost penalty"]:
                row(f"{prm}, {mass}",
                    run([os.path.join(ROOT, "prm", prm),
                         "--set", "Basis/Type=bspline",
                         "--set", f"Mass matrix/Type={mass}"]))


if __name__ == "__main__":
    main()
