#!/usr/bin/python3
"""Where a free elastic bar's energy goes: amplitude, time step, motion
across the grid, stiffness and particle count, one entry at a time.

prm/free_vibrating_bar.prm (free-free bar, first axial mode v0 cos(pi (x -
3) / L), 15 s = three periods) with the changes of CASES, each for
Powell-Sabin's default (lumped mass, apic), lumped Powell-Sabin with musl
and P1's default (ghost penalty, musl). Prints one markdown table
(doc/transfers.md, "Free bodies without numerical damping"): the
fraction of the vibration's energy lost over the run,

    (E_0 - E_end) / (E_0 - 1/2 M U^2),

E = total_energy + affine_kinetic_energy (free_body_transfers.energy():
the stability monitor's energy plus the affine fields' part), U the rigid translation the case adds, M
the bar's mass. A translation is carried exactly by every transfer, so
what is lost is the vibration's.

    /usr/bin/python3 contrib/studies/stability/free_bar_damping_sources.py \\
        [--psmpm build/psmpm] [--work DIR]
"""
import argparse
import os
import tempfile

# The runs and energies of the free-body table (the script's own directory
# is on the path).
from free_body_transfers import ROOT, energy, run

MODE = "v0*cos(pi*(x-3)/L)"
MASS = 25 * 2 * 1.0  # length x height x density of the bar's particles


def velocity(v0, U=0.0):
    return ["Initial conditions/Function constants=v0=%g, L=25" % v0,
            "Initial conditions/Velocity=%s+%g; 0" % (MODE, U)]


# name, --set entries, translation U
CASES = [
    ("v0 = 0.001 (ends move 0.0008 of a cell)", velocity(0.001), 0.0),
    ("v0 = 0.01", velocity(0.01), 0.0),
    ("v0 = 0.1 (the scene; ends move 0.08 of a cell)", velocity(0.1), 0.0),
    ("v0 = 0.3 (ends move 0.24 of a cell)", velocity(0.3), 0.0),
    ("v0 = 0.1, Courant number 0.25", velocity(0.1) +
     ["Time/Courant number=0.25"], 0.0),
    ("v0 = 0.1, Courant number 0.125", velocity(0.1) +
     ["Time/Courant number=0.125"], 0.0),
    ("v0 = 0.01 plus a translation U = 0.05 (0.75 cells)",
     velocity(0.01, 0.05), 0.05),
    ("the same, 6 x 6 particles per block", velocity(0.01, 0.05) +
     ["Particles/Per block x=6", "Particles/Per block y=6"], 0.05),
    ("the same, 4 x 4 particles, E = 1e-8 (no stiffness), dt = 0.03",
     velocity(0.01, 0.05) + ["Material/Young's modulus=1e-8",
                             "Time/Time step=0.03"], 0.05),
    ("v0 = 0.01, E = 1e-8 (no stiffness), dt = 0.03", velocity(0.01) +
     ["Material/Young's modulus=1e-8", "Time/Time step=0.03"], 0.0),
]

TRANSFERS = [
    ("PS default (lumped, apic)", ["Basis/Type=powell-sabin"]),
    ("PS lumped, musl", ["Basis/Type=powell-sabin", "Mass matrix/Type=lumped",
                         "Transfer/Scheme=musl"]),
    ("P1 default (ghost penalty, musl)", ["Basis/Type=linear"]),
]


def lost_fraction(psmpm, out, settings, U):
    summary, s, status, _ = run(psmpm, "free_vibrating_bar.prm", out, settings)
    if summary is None or summary["status"] != "completed":
        return status
    e = energy(s)
    vibration = e[0] - 0.5 * MASS * U * U
    return "%.4f" % ((e[0] - e[-1]) / vibration)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--psmpm", default=os.path.join(ROOT, "build", "psmpm"))
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="psmpm-bar-damping-")
    print("| case | " + " | ".join(t for t, _ in TRANSFERS) + " |")
    print("|---" * (len(TRANSFERS) + 1) + "|")
    for i, (name, settings, U) in enumerate(CASES):
        cells = []
        for j, (_, transfer) in enumerate(TRANSFERS):
            out = os.path.join(work, "case%02d-%d" % (i, j))
            cells.append(lost_fraction(args.psmpm, out, transfer + settings, U))
        print("| %s | %s |" % (name, " | ".join(cells)), flush=True)


if __name__ == "__main__":
    main()
