#!/usr/bin/python3
"""BSMPM in 2D beside PS-MPM: quadratic tensor-product B-splines on a
Cartesian mesh of rectangles (Basis/Type = bspline, Mesh/Type = cartesian)
against Powell-Sabin splines on criss-cross triangles, with the same
particles, on

* the thesis' small-deformation bar (prm/vibrating_bar_small_ps.prm,
  consistent mass, 1 to 16 blocks in x; B-splines to 32), and
* the soil column (prm/soil_column_small.prm, 4 to 32 blocks in y;
  B-splines with lumped and consistent mass, Powell-Sabin with consistent
  and partially lumped mass).

Prints, per run, the displacement L2 error at the end (and its rate under
refinement), the stress error, the number of basis functions, the CPU
seconds of the time loop (summary.json cpu_time_loop_s), the CPU seconds
of the whole process (user + sys of the child, getrusage) and the wall
seconds: error against run time. Markdown tables for doc/chapter.md.

    /usr/bin/python3 contrib/studies/chapter/bsmpm_2d_study.py [--psmpm build/psmpm]

Debian python3 only.
"""
import argparse
import json
import math
import os
import resource
import subprocess
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def run(psmpm, prm, settings, directory):
    out = os.path.join(directory, "run-%d" % len(os.listdir(directory)))
    command = [psmpm, os.path.join(ROOT, "prm", prm),
               "--set", "Output directory=" + out,
               "--set", "Output/Interval=0"]
    for key, value in settings.items():
        command += ["--set", "%s=%s" % (key, value)]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    subprocess.run(command, check=False, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime -
                                                  before.ru_stime)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return summary, cpu, wall


def table(psmpm, title, prm, direction, methods, directory):
    print("\n### %s\n" % title)
    print("| method | blocks | functions | status | E_u | rate | stress error "
          "| loop CPU s | process CPU s | wall s |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, settings, counts in methods:
        previous = None
        for n in counts:
            s = dict(settings)
            s["Mesh/Blocks " + direction] = n
            summary, cpu, wall = run(psmpm, prm, s, directory)
            e = summary.get("errors", {})
            eu = e.get("displacement_L2", float("nan"))
            rate = ("%.2f" % math.log2(previous / eu)
                    if previous and summary["status"] == "completed" else "")
            previous = eu if summary["status"] == "completed" else None
            print("| %s | %d | %d | %s | %.4e | %s | %.3e | %.2f | %.2f | "
                  "%.2f |" % (name, n, summary["n_dofs"], summary["status"],
                              eu, rate, e.get("stress_L2", float("nan")),
                              summary["cpu_time_loop_s"], cpu, wall))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--psmpm", default=os.path.join(ROOT, "build",
                                                        "psmpm"))
    args = parser.parse_args()
    bspline = {"Mesh/Type": "cartesian", "Basis/Type": "bspline",
               "Basis/Degree": 2}
    ps = {"Mesh/Type": "criss-cross", "Basis/Type": "powell-sabin"}
    with tempfile.TemporaryDirectory() as directory:
        table(args.psmpm,
              "Thesis bar (prm/vibrating_bar_small_ps.prm), consistent mass",
              "vibrating_bar_small_ps.prm", "x",
              [("PS, criss-cross", dict(ps, **{"Mass matrix/Type":
                                               "consistent"}),
                [1, 2, 4, 8, 16]),
               ("BSMPM p = 2, cartesian",
                dict(bspline, **{"Mass matrix/Type": "consistent"}),
                [1, 2, 4, 8, 16, 32])],
              directory)
        table(args.psmpm,
              "Soil column (prm/soil_column_small.prm)",
              "soil_column_small.prm", "y",
              [("PS consistent", dict(ps, **{"Mass matrix/Type":
                                            "consistent"}),
                [4, 8, 16, 32]),
               ("PS partially lumped",
                dict(ps, **{"Mass matrix/Type": "partially lumped"}),
                [4, 8, 16, 32]),
               ("BSMPM consistent",
                dict(bspline, **{"Mass matrix/Type": "consistent"}),
                [4, 8, 16, 32]),
               ("BSMPM lumped",
                dict(bspline, **{"Mass matrix/Type": "lumped"}),
                [4, 8, 16, 32])],
              directory)


if __name__ == "__main__":
    main()
