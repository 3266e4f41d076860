#!/usr/bin/python3
"""Granular column collapse against the experimental laws, both bases.

  /usr/bin/python3 contrib/geomechanics/column_collapse_study.py
      [build/psmpm] [work dir] [--ratios 0.5,1,2,3,4] [--cells 20]
      [--bases linear,powell-sabin] [--floor 0.36|no-slip|frictionless]
      [--set "Section/Entry=value" ...]

prm/granular_column_collapse.prm (aluminium rods of Bui et al. 2008:
rho 2650 kg/m^3, E 0.84 MPa, nu 0.3, Mohr-Coulomb phi 19.8 deg, psi 0,
c 0, released from geostatic stress) with the initial width d0 = 0.2 m
and the height h0 = a d0 for each aspect ratio a, `--cells` cells over
h0, a domain long enough for the run-out the laws predict and an end
time of 12 sqrt(h0/g) (kinetic energy below 1e-3 of the released
gravitational energy there, which the table reports). Final height
h_inf = body1_y_max and run-out d_inf = body1_x_max (the front) at the
end, against the laws of Nguyen, Bui and Fukagawa for 2D aluminium-rod
columns:
  h_inf = h0                         (a < 0.65)
  h0 / h_inf = 1.42 a^(2/3)          (a > 0.65)
  (d_inf - d0) / d0 = 3.25 a^0.96    (0.65 < a < 1.5), 3.80 a^0.73 (a > 1.5)
From the last particle output also h_wall (the highest particle within
one cell of the wall: equal to body1_y_max unless a particle was thrown
up), V/V0 (the particles' total volume over the initial one: the
deposit's dilation) and the number n_ahead of particles beyond the
deposit's front d_front = body1_x_front (Output/Deposit front gap = one
cell: the particles sorted by x, the last one before the first gap of
more than one cell; the few thrown ahead of the deposit set body1_x_max
alone). The floor is the scene's (rough: Coulomb friction with mu = 1e6,
sticking wherever the floor pushes) unless --floor gives a friction
coefficient, no-slip or frictionless.
Writes column_collapse.tsv and column_collapse.png into the work
directory (copy them to doc/data/ and doc/images/), prints the table with
CPU and wall seconds per run. Reports; never fails on numbers.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import matplotlib
matplotlib.use("Agg")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
from psmpm_output import vtu_arrays  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
parser = argparse.ArgumentParser()
parser.add_argument("binary", nargs="?", default=os.path.join(here, "build", "psmpm"))
parser.add_argument("work", nargs="?", default=None)
parser.add_argument("--ratios", default="0.5,1,2,3,4")
parser.add_argument("--cells", type=int, default=20)
parser.add_argument("--bases", default="linear,powell-sabin")
parser.add_argument("--floor", default="")
parser.add_argument("--set", action="append", default=[],
                    help="an extra psmpm --set entry for every run")
# Per basis the transfer: Powell-Sabin with MUSL keeps the energy books
# (lumped mass); P1 with MUSL goes unstable at the toe of a cohesionless
# flow, so P1 runs with APIC (doc/geomechanics.md).
parser.add_argument("--transfers", default="linear:musl,powell-sabin:musl")
args = parser.parse_args()
work = args.work or tempfile.mkdtemp(prefix="psmpm-column-collapse.")
os.makedirs(work, exist_ok=True)

d0, g = 0.2, 9.81


def law_height(a):
    return 1.0 if a < 0.65 else 1.0 / (1.42 * a ** (2.0 / 3.0))


def law_runout(a):
    """(d_inf - d0)/d0, or None below a = 0.65 (no law given there)."""
    if a < 0.65:
        return None
    return 3.25 * a ** 0.96 if a < 1.5 else 3.80 * a ** 0.73


def floor_settings(floor):
    if not floor:
        return []
    if floor == "no-slip":
        return ["--set", "Boundary conditions/Fixed x=left, bottom",
                "--set", "Boundary conditions/Friction coefficient="]
    if floor == "frictionless":
        return ["--set", "Boundary conditions/Friction coefficient="]
    return ["--set", f"Boundary conditions/Friction coefficient=bottom: {floor}"]


def first_and_last_rows(path):
    names, first, row = [], None, None
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                part = line[1:].strip().split(":", 1)
                if len(part) == 2 and part[0].strip().isdigit():
                    names.append(part[1].strip())
            elif line.strip():
                row = line.split()
                first = first or row
    return (dict(zip(names, map(float, first))),
            dict(zip(names, map(float, row))))


def deposit(out, h):
    """The deposit from the last particle output: the total volume over
    the initial one, and the height at the wall (the highest particle
    within one cell of it, against body1_y_max: a particle thrown up
    would show as a difference)."""
    last = max(f for f in os.listdir(out) if f.startswith("particles-") and f.endswith(".000.vtu"))
    p = vtu_arrays(os.path.join(out, last))
    initial = sum(v / r for v, r in zip(p["volume"], p["volume_ratio"]))
    at_wall = [pt[1] for pt in p["Points"] if pt[0] < h]
    xs = sorted(pt[0] for pt in p["Points"])
    gap = next((i for i in range(len(xs) - 1) if xs[i + 1] - xs[i] > h), len(xs) - 1)
    return (sum(p["volume"]) / initial, max(at_wall) if at_wall else float("nan"),
            xs[gap], len(xs) - 1 - gap)


def run(a, basis):
    h0 = a * d0
    h = h0 / args.cells
    ro = law_runout(a)
    length = d0 * (1 + 1.5 * (ro if ro is not None else 2.0)) + 0.05
    # Room above: a few particles splash up at the impact of the front.
    height = 1.5 * h0
    nx, ny = math.ceil(length / h), math.ceil(height / h)
    end = 12 * math.sqrt(h0 / g)
    out = os.path.join(work, f"a{a}_{basis}")
    command = [args.binary, os.path.join(here, "prm", "granular_column_collapse.prm"),
               "--set", f"Output directory={out}",
               "--set", f"Basis/Type={basis}",
               "--set", f"Transfer/Scheme={transfers[basis]}",
               "--set", f"Geometry/Length={nx * h}",
               "--set", f"Geometry/Height={ny * h}",
               "--set", f"Mesh/Blocks x={nx}",
               "--set", f"Mesh/Blocks y={ny}",
               "--set", f"Bodies/Body 1/Corners=0, 0, {d0}, {h0}",
               "--set", f"Time/End time={end}",
               "--set", "Output/Interval=0",
               "--set", f"Output/Deposit front gap={h}"] + floor_settings(args.floor)
    for entry in args.set:
        command += ["--set", entry]
    start = time.time()
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.time() - start
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    if result.returncode != 0:
        print(f"a = {a} {basis}: exit {result.returncode}: {summary.get('reason', '')}", file=sys.stderr)
    first, row = first_and_last_rows(os.path.join(out, "statistics.txt"))
    volume, wall_height, front, ahead = deposit(out, h)
    # The statistics column body1_x_front is the same measure, every step.
    if abs(row["body1_x_front"] - front) > 1e-6 * d0:
        print(f"a = {a} {basis}: body1_x_front {row['body1_x_front']} != {front} from the particles",
              file=sys.stderr)
    released = -row["gravity_energy"] if row["gravity_energy"] < 0 else float("nan")
    # What is conserved: total (kinetic + strain + gravity + dissipated)
    # minus the floor's friction work.
    balance = (row["total_energy"] - row.get("friction_work", 0)) - first["total_energy"]
    return {
        "a": a, "basis": basis, "status": summary["status"],
        "h_ratio": row["body1_y_max"] / h0,
        "h_wall": wall_height / h0, "volume": volume,
        "runout": (row["body1_x_max"] - d0) / d0,
        "front": (front - d0) / d0, "ahead": ahead,
        "kinetic_fraction": row["kinetic_energy"] / released if released > 0 else float("nan"),
        "energy_error": balance / released if released > 0 else float("nan"),
        "cpu": summary.get("cpu_time_s", float("nan")), "wall": wall,
        "particles": summary.get("n_particles", 0), "steps": summary.get("steps", 0),
    }


transfers = dict(x.split(":") for x in args.transfers.split(","))
rows = []
for a in [float(x) for x in args.ratios.split(",")]:
    for basis in args.bases.split(","):
        rows.append(run(a, basis))
        r = rows[-1]
        print(f"a {a:4.2f} {basis:13s} h_inf/h0 {r['h_ratio']:.3f} (law {law_height(a):.3f})"
              f"  (d_inf-d0)/d0 {r['runout']:.3f}"
              f" (law {law_runout(a) if law_runout(a) is not None else float('nan'):.3f})"
              f"  front {r['front']:.3f} ({r['ahead']} ahead)"
              f"  h_wall/h0 {r['h_wall']:.3f} V/V0 {r['volume']:.2f}"
              f"  Ek/released {r['kinetic_fraction']:.1e} energy {r['energy_error']:+.1e}  CPU {r['cpu']:.1f} s wall {r['wall']:.1f} s"
              f"  {r['status']}", flush=True)

with open(os.path.join(work, "column_collapse.tsv"), "w") as f:
    f.write("a\tbasis\th_inf/h0\tlaw\terror\t(d_inf-d0)/d0\tlaw\terror\tEk/released\t"
            "energy_error\tcpu_s\twall_s\tparticles\tsteps\tstatus\th_wall/h0\tV/V0\t"
            "(d_front-d0)/d0\terror\tn_ahead\n")
    for r in rows:
        lh, lr = law_height(r["a"]), law_runout(r["a"])
        f.write(f"{r['a']}\t{r['basis']}\t{r['h_ratio']:.4f}\t{lh:.4f}\t{r['h_ratio'] / lh - 1:+.3f}\t"
                f"{r['runout']:.4f}\t{lr if lr is not None else 'nan'}\t"
                f"{(r['runout'] / lr - 1) if lr else float('nan'):+.3f}\t{r['kinetic_fraction']:.2e}\t"
                f"{r['energy_error']:.2e}\t{r['cpu']:.2f}\t{r['wall']:.2f}\t{r['particles']}\t"
                f"{r['steps']}\t{r['status']}\t{r['h_wall']:.4f}\t{r['volume']:.3f}\t"
                f"{r['front']:.4f}\t{(r['front'] / lr - 1) if lr else float('nan'):+.3f}\t{r['ahead']}\n")

fig, axes = plt.subplots(1, 2, figsize=(10, 4))
ax = [x / 100 for x in range(30, 460)]
axes[0].plot(ax, [1 / law_height(a) for a in ax], "k-", label="Nguyen et al. law")
axes[1].plot([a for a in ax if a > 0.65], [law_runout(a) for a in ax if a > 0.65], "k-",
             label="Nguyen et al. law")
for basis, marker in (("linear", "o"), ("powell-sabin", "s")):
    # Runs that stopped early (a particle thrown out of the mesh) are in
    # the table, not in the plot.
    sel = [r for r in rows if r["basis"] == basis and r["status"] == "completed"]
    axes[0].plot([r["a"] for r in sel], [1 / r["h_ratio"] for r in sel], marker, label=basis)
    axes[1].plot([r["a"] for r in sel], [r["runout"] for r in sel], marker, label=basis)
    axes[1].plot([r["a"] for r in sel], [r["front"] for r in sel], marker, mfc="none",
                 label=basis + ", deposit front")
axes[0].set_xlabel("a = h0/d0")
axes[0].set_ylabel("h0 / h_inf")
axes[1].set_xlabel("a = h0/d0")
axes[1].set_ylabel("(d_inf - d0) / d0")
for x in axes:
    x.grid(True, alpha=0.3)
    x.legend()
fig.tight_layout()
fig.savefig(os.path.join(work, "column_collapse.png"), dpi=120)
print(f"wrote {work}/column_collapse.tsv and column_collapse.png")
