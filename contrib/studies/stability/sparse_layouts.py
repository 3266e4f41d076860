#!/usr/bin/python3
"""Sparse particle layouts on the thesis bar (prm/vibrating_bar_small_ps.prm,
Powell-Sabin, Mass matrix/Type = automatic, to t = 0.2 s): for each
Mass matrix/Sampling stabilization value, runs criss-cross and diagonal
meshes of 2 and 8 blocks with 1 x 1 ... 16 x 14 particles per block, at
dt = 1e-3 and at the automatic time step (Time step = 0), and counts the
runs that end unstable (doc/stability.md, "Sparse particle layouts").

    [TARGETS="0 0.5 1"] [BASELINE=old/sparse_layouts.tsv] \
        /usr/bin/python3 contrib/studies/stability/sparse_layouts.py [build/psmpm] [work dir]
Writes sparse_layouts.tsv (one row per run) into the work directory. With
BASELINE (the tsv of an earlier binary), also prints per target the
geometric mean of E_u / E_u(baseline) over the runs at dt = 1e-3 that
completed in both, and the runs more than 2x worse."""
import json, os, subprocess, sys, tempfile

here = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
binary = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "build", "psmpm")
work = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="psmpm-sparse.")
targets = os.environ.get("TARGETS", "0 0.5 1").split()
layouts = ["1x1", "2x1", "2x2", "3x2", "2x3", "3x3", "5x2", "4x4", "6x5", "16x14"]
os.makedirs(work, exist_ok=True)
rows = []
for target in targets:
    for mesh in ["criss-cross", "diagonal"]:
        for blocks in [2, 8]:
            for layout in layouts:
                px, py = layout.split("x")
                for dt in ["1e-3", "0"]:
                    out = os.path.join(work, "run")
                    subprocess.run(
                        [binary, os.path.join(here, "prm", "vibrating_bar_small_ps.prm")]
                        + [a for s in [f"Mesh/Type={mesh}", f"Mesh/Blocks x={blocks}",
                                       f"Particles/Per block x={px}",
                                       f"Particles/Per block y={py}",
                                       "Mass matrix/Type=automatic",
                                       f"Mass matrix/Sampling stabilization={target}",
                                       f"Time/Time step={dt}", "Time/End time=0.2",
                                       "Output/Interval=0", f"Output directory={out}"]
                           for a in ("--set", s)],
                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                    j = json.load(open(os.path.join(out, "summary.json")))
                    rows.append((target, mesh, blocks, layout, dt, j["status"],
                                 j["errors"]["displacement_L2"], j["steps"]))
with open(os.path.join(work, "sparse_layouts.tsv"), "w") as f:
    f.write("target\tmesh\tblocks\tlayout\tdt\tstatus\tE_u\tsteps\n")
    for r in rows:
        f.write("\t".join(str(x) for x in r) + "\n")
print("target  unstable at dt=1e-3  unstable at automatic dt  (of %d each)"
      % (len(rows) // (2 * len(targets))))
for t in targets:
    n = [sum(1 for r in rows if r[0] == t and r[4] == dt and r[5] != "completed")
         for dt in ("1e-3", "0")]
    print("%-7s %-20d %d" % (t, n[0], n[1]))
print("16 x 14 per block, E_u at dt = 1e-3:")
for r in rows:
    if r[3] == "16x14" and r[4] == "1e-3":
        print("  target %s %s %d blocks: %.4e" % (r[0], r[1], r[2], r[6]))
print("unstable at the automatic step, last target:",
      ", ".join("%s %d %s" % (r[1], r[2], r[3]) for r in rows
                if r[0] == targets[-1] and r[4] == "0" and r[5] != "completed"))
baseline = os.environ.get("BASELINE")
if baseline:
    old = {}
    for line in open(baseline).read().split("\n")[1:]:
        f = line.split("\t")
        if len(f) == 8:
            old[(f[0], f[1], f[2], f[3], f[4])] = (f[5], float(f[6]))
    import math
    for t in targets:
        logs, worse = [], []
        for r in rows:
            key = (r[0], r[1], str(r[2]), r[3], r[4])
            if r[0] != t or r[4] != "1e-3" or key not in old:
                continue
            status, e_old = old[key]
            if status == "completed" and r[5] == "completed" and e_old > 0:
                logs.append(math.log(r[6] / e_old))
                if r[6] > 2 * e_old:
                    worse.append("%s %d %s %.2e -> %.2e" % (r[1], r[2], r[3], e_old, r[6]))
        if logs:
            print("target %s against the baseline: geometric mean of E_u ratio %.3f over %d runs; > 2x: %s"
                  % (t, math.exp(sum(logs) / len(logs)), len(logs), "; ".join(worse) or "none"))
