#!/usr/bin/python3
"""Iterations and cost of Jacobi-CG, AMG-CG and pmg-CG (p-multigrid V-cycle,
Powell-Sabin only) on psmpm's own consistent particle mass matrices
(part 2 of doc/solver_study.md).

  /usr/bin/python3 contrib/studies/solvers/particle_mass_solvers.py

Runs the thesis bar (P1 and Powell-Sabin), the soil column (P1 on 2 x 16
blocks, Powell-Sabin on 1 x 8) and the large soil column on 1 x 8 blocks up
to t = 0.115 s, where its top element is nearly empty (the thesis' failing
consistent Powell-Sabin case), each with Mass matrix/Type = consistent,
Solver tolerance = 1e-8 and MUSL (two solves of dim components per step),
Direct solver size = 0 (CG everywhere), once with each Preconditioner
(jacobi, amg, and pmg for Powell-Sabin). Per case the step with
the largest Jacobi-CG condition estimate is reported: the CG iterations of
that step (all 2 * dim solves: components fixed everywhere or with a zero
right-hand side take none) and deal.II's CG estimate of the
condition number of the Jacobi-preconditioned matrix (the unpreconditioned
condition number is not measured in the MPM runs), the mean iterations
per step over the run, the "solve" and "particle to grid" (assembly and
preconditioner set-up) wall timers per step and the process CPU seconds
(user + sys, /usr/bin/time). Writes doc/data/particle_mass_solvers.tsv
(the columns of solver_study.tsv first) and, unless PSMPM_THROUGHPUT=0,
doc/data/particle_mass_solvers_throughput.tsv: prm/benchmark_throughput.prm
with Powell-Sabin, consistent and partially lumped mass, for 20 steps
(Solver tolerance 1e-12 there, the run's default).
"""
import json
import os
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.environ.get("PSMPM_BINARY", os.path.join(ROOT, "build", "psmpm"))

# name, prm, degree, blocks (x, y) for 1/h, extra settings
CASES = [
    ("p1 thesis bar", "vibrating_bar_small.prm", 1, ["Time/End time=1e-4"]),
    ("ps thesis bar", "vibrating_bar_small_ps.prm", 2,
     ["Time/End time=1e-4"]),
    ("p1 thesis bar 32 blocks", "vibrating_bar_small.prm", 1,
     ["Time/End time=1e-4", "Mesh/Blocks x=32", "Mesh/Blocks y=4"]),
    ("ps thesis bar 32 blocks", "vibrating_bar_small_ps.prm", 2,
     ["Time/End time=1e-4", "Mesh/Blocks x=32", "Mesh/Blocks y=4",
      "Particles/Per block x=8", "Particles/Per block y=6"]),
    ("p1 soil column", "soil_column_small.prm", 1,
     ["Time/End time=5e-3", "Basis/Type=linear", "Mesh/Blocks x=2",
      "Mesh/Blocks y=16", "Particles/Per block x=3",
      "Particles/Per block y=4"]),
    ("ps soil column", "soil_column_small.prm", 2, ["Time/End time=5e-3"]),
    ("ps nearly empty", "soil_column_large.prm", 2,
     ["Time/End time=0.115", "Mesh/Blocks y=8",
      "Reference solution/Type=none"]),
]


PRECONDITIONERS = ["jacobi", "amg", "pmg"]


def run(prm, sets, preconditioner, extra=()):
    """Run a scene; return its statistics rows, summary.json and the
    process' user + sys CPU seconds (/usr/bin/time)."""
    out = tempfile.mkdtemp(prefix="psmpm-pmass-")
    cmd = ["/usr/bin/time", "-f", "%U %S %e", "-o",
           os.path.join(out, "time.txt"), BIN, os.path.join(ROOT, "prm", prm),
           "--set", f"Output directory={out}", "--set", "Output/Interval=0",
           "--set", "Mass matrix/Type=consistent", "--set",
           "Mass matrix/Solver tolerance=1e-8", "--set",
           f"Mass matrix/Preconditioner={preconditioner}", "--set",
           "Mass matrix/Maximum iterations=100000", "--set",
           "Mass matrix/Direct solver size=0", "--set",
           "Transfer/Scheme=musl"]
    for s in list(sets) + list(extra):
        cmd += ["--set", s]
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    names, rows = [], []
    with open(os.path.join(out, "statistics.txt")) as f:
        for line in f:
            if line.startswith("#"):
                names.append(line.split(":", 1)[1].strip())
            elif line.strip():
                rows.append(dict(zip(names, line.split())))
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "time.txt")) as f:
        user, system, wall = (float(x) for x in f.read().split()[-3:])
    return rows, summary, user + system, wall


def main():
    table = os.path.join(ROOT, "doc", "data", "particle_mass_solvers.tsv")
    with open(table, "w") as out:
        out.write("matrix\tdegree\tinverse_h\tn_dofs\tcondition_number\t"
                  "cg_iterations\tjacobi_cg_iterations_per_step\t"
                  "amg_cg_iterations_per_step\tpmg_vcycles\t"
                  "pmg_cg_iterations_per_step\t"
                  "jacobi_mean_iterations\tamg_mean_iterations\t"
                  "pmg_mean_iterations\t"
                  "jacobi_solve_ms_per_step\tamg_solve_ms_per_step\t"
                  "pmg_solve_ms_per_step\t"
                  "jacobi_p2g_ms_per_step\tamg_p2g_ms_per_step\t"
                  "pmg_p2g_ms_per_step\t"
                  "jacobi_cpu_s\tamg_cpu_s\tpmg_cpu_s\tstep\tstatus\n")
        for name, prm, degree, sets in CASES:
            if degree == 1:
                # pmg is Powell-Sabin's (P1 is its coarse level).
                results = {p: run(prm, sets, p) for p in PRECONDITIONERS[:2]}
            else:
                results = {p: run(prm, sets, p) for p in PRECONDITIONERS}
            jac, summary, _, _ = results["jacobi"]
            # The step whose Jacobi-CG condition estimate is largest.
            k = max(range(len(jac)),
                    key=lambda i: float(jac[i]["condition_number"]))

            def col(p, f):
                return f(*results[p]) if p in results else "-"

            def at_k(rows, *_):
                return rows[k]["cg_iterations"] if k < len(rows) else "-"

            def mean(rows, *_):
                return f"{sum(int(r['cg_iterations']) for r in rows) / max(len(rows), 1):.1f}"

            def per_step_ms(timer):
                return lambda rows, s, *_: (
                    f"{1e3 * s.get('timers_s', {}).get(timer, 0) / max(s['steps'], 1):.3g}")

            def cpu(rows, s, c, w):
                return f"{c:.2f}"

            statuses = ",".join(f"{p}:{results[p][1]['status']}"
                                for p in results)
            fields = [name, degree, "-", summary["n_dofs"],
                      f"{float(jac[k]['condition_number']):.4e}", "-",
                      col("jacobi", at_k), col("amg", at_k), "-",
                      col("pmg", at_k)]
            fields += [col(p, mean) for p in PRECONDITIONERS]
            fields += [col(p, per_step_ms("solve")) for p in PRECONDITIONERS]
            fields += [col(p, per_step_ms("particle_to_grid"))
                       for p in PRECONDITIONERS]
            fields += [col(p, cpu) for p in PRECONDITIONERS]
            fields += [jac[k]["step"], statuses]
            line = "\t".join(str(x) for x in fields) + "\n"
            out.write(line)
            print(line, end="", flush=True)
    if os.environ.get("PSMPM_THROUGHPUT", "1") == "1":
        throughput()


def throughput():
    """prm/benchmark_throughput.prm (closed bar, 320,000 particles) with
    Powell-Sabin, consistent and partially lumped (Powell-Sabin's default
    there) mass, 20 steps, each preconditioner, one process: run CPU
    (user + sys) beside wall and the summary's phase timers."""
    table = os.path.join(ROOT, "doc", "data",
                         "particle_mass_solvers_throughput.tsv")
    with open(table, "w") as out:
        out.write("mass\tpreconditioner\tn_dofs\tn_particles\tsteps\t"
                  "cg_iterations_per_step\tcpu_user_sys_s\twall_s\t"
                  "loop_cpu_s\tsolve_s\tparticle_to_grid_s\tstatus\n")
        for mass in ["consistent", "partially lumped"]:
            sets = ["Basis/Type=powell-sabin", "Time/End time=2e-4",
                    f"Mass matrix/Type={mass}"]
            for p in PRECONDITIONERS:
                rows, s, c, w = run("benchmark_throughput.prm", sets, p,
                                    ["Mass matrix/Solver tolerance=1e-12"])
                t = s.get("timers_s", {})
                line = (f"{mass}\t{p}\t{s['n_dofs']}\t{s['n_particles']}\t"
                        f"{s['steps']}\t"
                        f"{s['cg_iterations'] / max(s['steps'], 1):.1f}\t"
                        f"{c:.2f}\t{w:.2f}\t"
                        f"{s.get('cpu_time_loop_s', 0):.2f}\t"
                        f"{t.get('solve', 0):.2f}\t"
                        f"{t.get('particle_to_grid', 0):.2f}\t"
                        f"{s['status']}\n")
                out.write(line)
                print(line, end="", flush=True)


if __name__ == "__main__":
    main()
