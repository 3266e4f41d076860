#!/usr/bin/python3
"""Point Jacobi against vertex-block Jacobi (Mass matrix/Preconditioner =
jacobi | block jacobi) for Powell-Sabin mass solves: the Powell-Sabin cases
of contrib/studies/solvers/particle_mass_solvers.py (consistent mass, CG to 1e-8, every
system through CG) and the closed throughput bar with the default mass
(partially lumped, CG to 1e-12, 40 steps). Per case and preconditioner:
mean CG iterations per step, the largest CG condition estimate of the run,
CPU and wall seconds of the whole run (user + sys, and elapsed, from one
/usr/bin/time) and the relative
difference of the final total energy between the two. Prints a markdown
table (doc/performance.md, "Block Jacobi").

    /usr/bin/python3 contrib/studies/solvers/block_jacobi_study.py     # ~3 min
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import particle_mass_solvers as pms  # noqa: E402

THROUGHPUT = ("ps throughput bar, closed, default mass",
              "benchmark_throughput.prm", 2,
              ["Basis/Type=powell-sabin", "Mass matrix/Type=automatic",
               "Mass matrix/Solver tolerance=1e-12"])


def measure(case, preconditioner):
    name, prm, degree, sets = case
    rows, summary, cpu, wall = pms.run(prm, sets, preconditioner)
    its = [float(r["cg_iterations"]) for r in rows]
    cond = [float(r["condition_number"]) for r in rows
            if r.get("condition_number", "-") not in ("-", "nan")]
    energy = float(rows[-1]["total_energy"])
    return (sum(its) / max(len(its), 1), max(cond) if cond else 0.0, cpu,
            energy, summary["status"], wall)


def main():
    cases = [c for c in pms.CASES if c[2] == 2] + [THROUGHPUT]
    print("| case | mean CG its/step jacobi / block | largest cond. "
          "estimate jacobi / block | CPU s jacobi / block | wall s jacobi / "
          "block | final energy "
          "rel. difference | status |")
    print("|---|---|---|---|---|---|---|")
    for case in cases:
        j = measure(case, "jacobi")
        b = measure(case, "block jacobi")
        diff = abs(b[3] - j[3]) / max(abs(j[3]), 1e-300)
        print(f"| {case[0]} | {j[0]:.1f} / {b[0]:.1f} | {j[1]:.3g} / "
              f"{b[1]:.3g} | {j[2]:.2f} / {b[2]:.2f} | {j[5]:.2f} / {b[5]:.2f} | "
              f"{diff:.1e} | "
              f"{j[4]} / {b[4]} |", flush=True)


if __name__ == "__main__":
    main()
