#!/usr/bin/python3
"""Iterations of Jacobi-CG and AMG-CG on psmpm's own consistent particle
mass matrices (issue 11, part 2 of doc/solver_study.md).

  /usr/bin/python3 contrib/particle_mass_solvers.py

Runs the thesis bar (P1 and Powell-Sabin), the soil column (P1 on 2 x 16
blocks, Powell-Sabin on 1 x 8) and the large soil column on 1 x 8 blocks up
to t = 0.115 s, where its top element is nearly empty (the thesis' failing
consistent Powell-Sabin case), each with Mass matrix/Type = consistent,
Solver tolerance = 1e-8 and MUSL (two solves of dim components per step),
once with Preconditioner = jacobi and once with amg. Per case the step with
the largest Jacobi-CG condition estimate is reported: the CG iterations of
that step (all 2 * dim solves: components fixed everywhere or with a zero
right-hand side take none) and deal.II's CG estimate of the
condition number of the Jacobi-preconditioned matrix (the unpreconditioned
condition number is not measured in the MPM runs). Writes
doc/data/particle_mass_solvers.tsv in the columns of solver_study.tsv.
"""
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
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


def run(prm, sets, preconditioner):
    out = tempfile.mkdtemp(prefix="psmpm-pmass-")
    cmd = [BIN, os.path.join(ROOT, "prm", prm), "--set",
           f"Output directory={out}", "--set", "Output/Interval=0",
           "--set", "Mass matrix/Type=consistent", "--set",
           "Mass matrix/Solver tolerance=1e-8", "--set",
           f"Mass matrix/Preconditioner={preconditioner}", "--set",
           "Mass matrix/Maximum iterations=100000", "--set",
           "Transfer/Scheme=musl"]
    for s in sets:
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
        summary = f.read()
    return rows, summary


def main():
    table = os.path.join(ROOT, "doc", "data", "particle_mass_solvers.tsv")
    with open(table, "w") as out:
        out.write("matrix\tdegree\tinverse_h\tn_dofs\tcondition_number\t"
                  "cg_iterations\tjacobi_cg_iterations_per_step\t"
                  "amg_cg_iterations_per_step\tpmg_vcycles\tstep\tstatus\n")
        for name, prm, degree, sets in CASES:
            jac, summary = run(prm, sets, "jacobi")
            amg, _ = run(prm, sets, "amg")
            # The step whose Jacobi-CG condition estimate is largest.
            k = max(range(len(jac)),
                    key=lambda i: float(jac[i]["condition_number"]))
            per_step = lambda rows: (
                rows[k]["cg_iterations"] if k < len(rows) else "-")
            n_dofs = summary.split('"n_dofs":')[1].split(",")[0].strip()
            status = summary.split('"status":')[1].split(",")[0].strip(
                ' "\n}')
            line = (f"{name}\t{degree}\t-\t{n_dofs}\t"
                    f"{float(jac[k]['condition_number']):.4e}\t-\t"
                    f"{per_step(jac)}\t{per_step(amg)}\t-\t"
                    f"{jac[k]['step']}\t{status}\n")
            out.write(line)
            print(line, end="", flush=True)


if __name__ == "__main__":
    main()
