#!/usr/bin/python3
"""Transfers on free bodies: numerical damping, angular momentum, collapse.

Runs every variant of VARIANTS on three scenes with the automatic time step
and prints one markdown table (doc/transfers.md, "Free bodies without
numerical damping"):

* prm/free_vibrating_bar.prm (Powell-Sabin, free-free bar in its first
  axial mode, three periods): total energy (with the affine fields'
  kinetic energy where the transfer carries them, which the stability
  monitor leaves out) at the end over the start, and
  the period from the kinetic energy's minima (at T/4, 3T/4, ...) over
  2 L / c;
* prm/rotating_block.prm (free block, quarter turn): angular momentum
  (with the affine part) at the end over the start, final rotation angle;
* prm/column_collapse.prm (elastic column on a frictionless floor):
  energy lost (initial minus final total energy, counted as for the bar)
  and the front
  (body1_x_max) at t = 1.5 s;

each with the CPU seconds (user + sys of the time loop, summary.json
cpu_time_loop_s) beside the wall seconds of the loop (time_loop_s).

    /usr/bin/python3 contrib/studies/stability/free_body_transfers.py \
        [--psmpm build/psmpm] [--work DIR] [--only NAME,...] [--set ENTRY=VALUE]

Runs go to DIR (default: a new directory under /tmp). --set is passed to
every run of every scene (e.g. --set "Particles/Per block x=3").
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "lib"))
from psmpm_output import ROOT, read_statistics, read_summary  # noqa: E402

# name -> --set entries (every run also gets the scene's basis below).
APIC = ["Mass matrix/Type=lumped", "Transfer/Scheme=apic"]
VARIANTS = [
    ("PS default (lumped, apic)", ["Mass matrix/Type=automatic",
                                   "Transfer/Scheme=automatic"]),
    ("apic, XPIC order 2", APIC + ["Transfer/XPIC order=2"]),
    ("apic, XPIC order 3", APIC + ["Transfer/XPIC order=3"]),
    ("apic, XPIC order 5", APIC + ["Transfer/XPIC order=5"]),
    ("apic, FLIP fraction 1 (AFLIP)", APIC + ["Transfer/FLIP fraction=1"]),
    ("apic, affine FLIP 1, grid positions",
     APIC + ["Transfer/FLIP fraction=1", "Transfer/FLIP affine matrix=true",
             "Transfer/Position update=grid velocity"]),
    ("apic, affine FLIP 0.99, grid positions",
     APIC + ["Transfer/FLIP fraction=0.99",
             "Transfer/FLIP affine matrix=true",
             "Transfer/Position update=grid velocity"]),
    ("PS lumped, musl", ["Mass matrix/Type=lumped", "Transfer/Scheme=musl"]),
    ("P1 default (ghost penalty, musl)", ["Basis/Type=linear",
                                          "Mass matrix/Type=automatic",
                                          "Transfer/Scheme=automatic"]),
]
BAR_PERIOD = 5.0  # 2 L / c of prm/free_vibrating_bar.prm


def run(psmpm, prm, out, settings):
    command = [psmpm, os.path.join(ROOT, "prm", prm),
               "--set", "Output directory=" + out,
               "--set", "Output/Interval=0",
               "--set", "Time/Time step=0"]
    for s in settings:
        command += ["--set", s]
    subprocess.run(command, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    summary = read_summary(out)
    if summary is None:
        return None, None, "no summary", ""
    status = summary["status"]
    if status != "completed":
        status += " (%s)" % summary.get("reason", "")
    statistics = read_statistics(os.path.join(out, "statistics.txt"))
    cost = "%.2f / %.2f" % (summary["cpu_time_loop_s"],
                            summary["time_loop_s"])
    return summary, statistics, status, cost


def kinetic_minima(t, kinetic):
    """Times of the kinetic energy's minima: a parabola fitted (least
    squares) to each stretch below 0.3 of the initial kinetic energy that
    lies inside the run."""
    import numpy as np
    low = kinetic < 0.3 * kinetic[0]
    minima, i = [], 0
    while i < len(t):
        if not low[i]:
            i += 1
            continue
        j = i
        while j < len(t) and low[j]:
            j += 1
        if i > 0 and j < len(t) and j - i >= 3:
            c = np.polyfit(t[i:j] - t[i], kinetic[i:j], 2)
            minima.append(t[i] - c[1] / (2 * c[0]))
        i = j
    return minima


def energy(s):
    """Total energy of every row, with the affine fields' kinetic energy
    where the transfer carries them (the stability monitor watches
    total_energy alone)."""
    return s["total_energy"] + s.get("affine_kinetic_energy", 0.)


def bar(result):
    summary, s, status, cost = result
    if summary is None or summary["status"] != "completed":
        return "%s | | %s" % (status, cost)
    e = energy(s)
    ratio = e[-1] / e[0]
    m = kinetic_minima(s["time"], s["kinetic_energy"])
    period = (2 * (m[-1] - m[0]) / (len(m) - 1) / BAR_PERIOD
              if len(m) > 1 else float("nan"))
    return "%.4f | %.4f | %s" % (ratio, period, cost)


def rotation(result):
    summary, s, status, cost = result
    if summary is None or summary["status"] != "completed":
        return "%s | | %s" % (status, cost)
    return "%.4f | %.4f | %s" % (
        1 + summary["angular_momentum_relative_change"],
        summary["rotation_angle_final"], cost)


def column(result):
    summary, s, status, cost = result
    if summary is None or summary["status"] != "completed":
        return "%s | | %s" % (status, cost)
    e = energy(s)
    lost = e[0] - e[-1]
    return "%.0f | %.3f | %s" % (lost, s["body1_x_max"][-1], cost)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--psmpm", default=os.path.join(ROOT, "build",
                                                        "psmpm"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--only", default=None,
                        help="comma-separated prefixes of variant names")
    parser.add_argument("--set", action="append", default=[])
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="psmpm-free-body-")
    print("runs in: %s\n" % work)
    print("| variant | bar energy end/start | bar period / (2L/c) | "
          "bar CPU / wall s | rotation L end/start | angle (pi/2 = 1.5708) | "
          "rotation CPU / wall s | column energy lost J | column front m | "
          "column CPU / wall s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for k, (name, settings) in enumerate(VARIANTS):
        if args.only and not any(name.startswith(o)
                                 for o in args.only.split(",")):
            continue
        cells = []
        for scene, prm, measure in (
                ("bar", "free_vibrating_bar.prm", bar),
                ("rotation", "rotating_block.prm", rotation),
                ("column", "column_collapse.prm", column)):
            basis = ([] if any(s.startswith("Basis/") for s in settings)
                     else ["Basis/Type=powell-sabin"])
            out = os.path.join(work, "%s_%d" % (scene, k))
            cells.append(measure(run(args.psmpm, prm, out,
                                     basis + settings + args.set)))
        print("| %s | %s |" % (name, " | ".join(cells)), flush=True)


if __name__ == "__main__":
    main()
