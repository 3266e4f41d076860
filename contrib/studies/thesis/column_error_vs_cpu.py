#!/usr/bin/python3
"""Error against CPU time on the thesis' soil columns, P1 and Powell-Sabin.

  [REPEATS=1] /usr/bin/python3 contrib/studies/thesis/column_error_vs_cpu.py [build/psmpm] [work dir]

Both columns of doc/benchmarks.md: the small one (prm/soil_column_small.prm,
Table 4.5, against the series solution) and the large one
(prm/soil_column_large.prm, Table 4.6, 18 % strain, against 1D ULFEM),
each on 1 x k criss-cross blocks with the scene's particles per block,
the defaults (Mass matrix/Type and Transfer/Scheme = automatic) and the
automatic time step (Time/Time step = 0, so that finer meshes get the
step they need). Error: the displacement error of thesis eq. 4.4 at the
end time (summary.json errors/displacement_L2); CPU: the time loop's CPU
seconds (summary.json cpu_time_loop_s, robust to other load on the
machine; the smallest of REPEATS runs), and the MPM's own time: the
wall seconds of the loop's MPM phases (timers_s: locate, particle to
grid, solve, grid to particle, update), without the statistics phase,
which holds the reference (the large column's 1D ULFEM with 2,000
elements, stepped alongside the run: 0.17-0.21 s whatever the mesh) and
the error norms. The plot and the comparison use the MPM phases; the
runs are short, so run them on an otherwise idle core. Writes column_error_vs_cpu.tsv
and column_error_vs_cpu.png into the work directory and prints, per
column, the cheapest run of each basis that reaches the smallest P1
error (P1's error need not fall with k: the particles per block stay
the scene's). Reports; never fails on numbers.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
binary = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "build", "psmpm")
work = sys.argv[2] if len(sys.argv) > 2 else tempfile.mkdtemp(prefix="psmpm-column-cpu.")
os.makedirs(work, exist_ok=True)
repeats = int(os.environ.get("REPEATS", "1"))

columns = {
    "small": ("soil_column_small.prm", [4, 8, 16, 32]),
    "large": ("soil_column_large.prm", [4, 8, 16]),
}


def run(column, prm, basis, k):
    out = os.path.join(work, f"{column}_{basis}_{k}")
    best = None
    for _ in range(repeats):
        subprocess.run([binary, os.path.join(here, "prm", prm),
                        "--set", f"Basis/Type={basis}",
                        "--set", "Mass matrix/Type=automatic",
                        "--set", "Transfer/Scheme=automatic",
                        "--set", "Mesh/Blocks x=1",
                        "--set", f"Mesh/Blocks y={k}",
                        "--set", "Time/Time step=0",
                        "--set", "Output/Interval=0",
                        "--set", f"Output directory={out}"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            j = json.load(open(os.path.join(out, "summary.json")))
        except (OSError, ValueError):
            return dict(status="no summary", error=math.nan, cpu=math.nan,
                        loop_cpu=math.nan, run_cpu=math.nan, particles=0,
                        steps=0)
        if j["status"] != "completed":
            return dict(status=j["status"], error=math.nan, cpu=math.nan,
                        loop_cpu=math.nan, run_cpu=math.nan,
                        particles=j["n_particles"], steps=j["steps"])
        mpm = sum(j["timers_s"].get(k, 0) for k in
                  ["locate", "particle_to_grid", "solve", "grid_to_particle",
                   "update"])
        if best is None or mpm < best["cpu"]:
            best = dict(status="completed",
                        error=j["errors"]["displacement_L2"],
                        cpu=mpm, loop_cpu=j["cpu_time_loop_s"],
                        run_cpu=j["cpu_time_s"],
                        particles=j["n_particles"], steps=j["steps"])
    return best


rows = []
print("column\tbasis\tblocks\tstatus\tparticles\tsteps\tE_u\tmpm_phases_s"
      "\tloop_cpu_s\trun_cpu_s", flush=True)
for column, (prm, meshes) in columns.items():
    for basis in ["linear", "powell-sabin"]:
        for k in meshes:
            r = run(column, prm, basis, k)
            r.update(column=column, basis=basis, blocks=k)
            rows.append(r)
            print(f"{column}\t{basis}\t1x{k}\t{r['status']}\t{r['particles']}"
                  f"\t{r['steps']}\t{r['error']:.4e}\t{r['cpu']:.3f}"
                  f"\t{r['loop_cpu']:.3f}\t{r['run_cpu']:.3f}", flush=True)

with open(os.path.join(work, "column_error_vs_cpu.tsv"), "w") as f:
    f.write("column\tbasis\tblocks\tstatus\tparticles\tsteps\tE_u\tmpm_phases_s"
            "\tloop_cpu_s\trun_cpu_s\n")
    for r in rows:
        f.write(f"{r['column']}\t{r['basis']}\t1x{r['blocks']}\t{r['status']}"
                f"\t{r['particles']}\t{r['steps']}\t{r['error']:.6e}"
                f"\t{r['cpu']:.4f}\t{r['loop_cpu']:.4f}\t{r['run_cpu']:.4f}\n")

fig, axes = plt.subplots(1, 2, figsize=(10, 4))
for ax, column in zip(axes, columns):
    for basis, style in [("linear", "o-"), ("powell-sabin", "s-")]:
        pts = [(r["cpu"], r["error"]) for r in rows
               if r["column"] == column and r["basis"] == basis
               and r["status"] == "completed"]
        if pts:
            ax.loglog(*zip(*pts), style, label="P1" if basis == "linear" else "Powell-Sabin")
    ax.set_xlabel("MPM phases of the time loop [s]")
    ax.set_ylabel("displacement error E_u")
    ax.set_title(f"soil column, {column} deformation")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(work, "column_error_vs_cpu.png"), dpi=110)

for column in columns:
    done = [r for r in rows if r["column"] == column and r["status"] == "completed"]
    p1 = [r for r in done if r["basis"] == "linear"]
    if not p1:
        continue
    best = min(p1, key=lambda r: r["error"])
    target = best["error"]
    print(f"{column}: target E_u {target:.4e} (the smallest P1 error, 1x{best['blocks']}, "
          f"MPM phases {best['cpu']:.3f} s)")
    for basis in ["linear", "powell-sabin"]:
        ok = [r for r in done if r["basis"] == basis and r["error"] <= target]
        if ok:
            c = min(ok, key=lambda r: r["cpu"])
            print(f"  cheapest {basis} at or below it: 1x{c['blocks']}, "
                  f"E_u {c['error']:.4e}, MPM phases {c['cpu']:.3f} s")
        else:
            print(f"  {basis}: no run at or below it")
print(f"plot: {os.path.join(work, 'column_error_vs_cpu.png')}")
