#!/usr/bin/python3
"""The large-deformation vibrating bar of Wobbes et al. 2019 (book chapter,
section 4.5, Fig. 4.7; prm/chapter_bar_1d_large.prm): v0 = 0.8 m/s, 20
elements, 8 particles per element, dt = 1e-5 s to T = 0.1 s, against the
updated Lagrangian FEM with 120 elements run alongside.

Runs MPM (linear basis), BSMPM (quadratic B-splines) and TLS-BSMPM
(Transfer/Reconstruction = taylor least squares), each with lumped and
consistent mass, MUSL, and the TLS variants (the chapter's fields with
the particles' lumped mass for the acceleration, Acceleration mass =
lumped; the centred velocity mapping, Fields = stress and centred
momentum; the stress alone); reads from summary.json the displacement,
velocity and stress L2 errors at T, the number of cell crossings and the
CPU seconds of the time loop (cpu_time_loop_s), beside the CPU (user + sys
of the child, getrusage) and wall seconds of the whole run; prints the table
with the stress error of MPM (lumped) over each method's, writes it into
doc/chapter.md (between the table markers) and plots the stress error
over time (statistics.txt) into doc/images/chapter_bar_large.png.

    /usr/bin/python3 contrib/studies/chapter/chapter_bar_large_study.py [--psmpm build/psmpm]
        [--no-write]

Debian python3 with matplotlib only.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
# (name, basis, mass, reconstruction, TLS fields, TLS acceleration mass)
SM = "stress and momentum"
CM = "stress and centred momentum"
MM = "mass matrix"
TLS = "taylor least squares"
METHODS = [("MPM", "linear", "lumped", "particles", SM, MM),
           ("MPM", "linear", "consistent", "particles", SM, MM),
           ("BSMPM", "bspline", "lumped", "particles", SM, MM),
           ("BSMPM", "bspline", "consistent", "particles", SM, MM),
           ("TLS-MPM (chapter)", "linear", "consistent", TLS, SM, MM),
           ("TLS-BSMPM (chapter)", "bspline", "lumped", TLS, SM, MM),
           ("TLS-BSMPM (chapter)", "bspline", "consistent", TLS, SM, MM),
           ("TLS-BSMPM (chapter), lumped acceleration", "bspline",
            "consistent", TLS, SM, "lumped"),
           ("TLS-BSMPM, centred momentum", "bspline", "lumped", TLS, CM, MM),
           ("TLS-BSMPM, centred momentum", "bspline", "consistent", TLS, CM,
            MM),
           ("TLS-BSMPM, centred momentum, lumped acceleration", "bspline",
            "consistent", TLS, CM, "lumped"),
           ("TLS-BSMPM, stress", "bspline", "lumped", TLS, "stress", MM),
           ("TLS-BSMPM, stress", "bspline", "consistent", TLS, "stress", MM)]
BEGIN = "<!-- chapter_bar_large_study table begin -->"
END = "<!-- chapter_bar_large_study table end -->"


def run(psmpm, basis, mass, reconstruction, fields, acceleration, directory):
    out = os.path.join(directory, "%s-%s-%s-%s-%s" % (
        basis, mass, reconstruction.split()[0], "-".join(fields.split()),
        acceleration.split()[0]))
    command = [psmpm, os.path.join(ROOT, "prm", "chapter_bar_1d_large.prm"),
               "--set", "Basis/Type=" + basis,
               "--set", "Mass matrix/Type=" + mass,
               "--set", "Transfer/Reconstruction=" + reconstruction,
               "--set", "Transfer/Taylor least squares/Fields=" + fields,
               "--set", "Transfer/Taylor least squares/Acceleration mass=" +
               acceleration,
               "--set", "Output directory=" + out]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    history = []
    if summary["status"] == "completed":
        with open(os.path.join(out, "statistics.txt")) as f:
            names = []
            for line in f:
                if line.startswith("#"):
                    # "# 1: time" style header lines
                    parts = line[1:].split(":", 1)
                    if len(parts) == 2 and parts[0].strip().isdigit():
                        names.append(parts[1].strip())
                    continue
                row = dict(zip(names, line.split()))
                if row.get("stress_L2", "-") != "-":
                    history.append((float(row["time"]),
                                    float(row["stress_L2"])))
    return summary, history, cpu, wall, result.returncode


def table(results):
    lines = ["| method | mass | status | u L2 error | v L2 error "
             "| stress L2 error | MPM lumped / this (stress) "
             "| cell crossings | loop CPU s | CPU s | wall s |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- "
             "| --- |"]
    reference = results[0][0]["errors"]["stress_L2"]
    for (name, basis, mass, _, _, _), (summary, _, cpu, wall, _) in zip(
            METHODS, results):
        if summary["status"] != "completed":
            lines.append("| %s | %s | %s: %s | - | - | - | - | - | - | %.2f "
                         "| %.2f |" % (name, mass, summary["status"],
                                     summary.get("reason", ""), cpu, wall))
            continue
        e = summary["errors"]
        lines.append("| %s | %s | completed | %.3e | %.3e | %.3e | %.1f | %d "
                     "| %.2f | %.2f | %.2f |" % (
                         name, mass, e["displacement_L2"], e["velocity_L2"],
                         e["stress_L2"], reference / e["stress_L2"],
                         summary["cell_crossings"],
                         summary["cpu_time_loop_s"], cpu, wall))
    return "\n".join(lines) + "\n"


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    for (name, _, mass, _, _, _), (_, history, _, _, _) in zip(METHODS,
                                                              results):
        if history:
            ax.semilogy([t for t, _ in history], [e for _, e in history],
                        label="%s %s" % (name, mass))
    ax.set_xlabel("time [s]")
    ax.set_ylabel("stress L2 error against ULFEM")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--psmpm", default=os.path.join(ROOT, "build",
                                                        "psmpm"))
    parser.add_argument("--no-write", action="store_true",
                        help="print the table only")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as directory:
        results = [run(args.psmpm, basis, mass, reconstruction, fields,
                       acceleration, directory)
                   for _, basis, mass, reconstruction, fields, acceleration
                   in METHODS]
    for (name, basis, mass, r, _, _), (_, _, _, _, code) in zip(METHODS,
                                                                results):
        # 3-7: a stability monitor stopped the run (reported in the table).
        if code not in (0, 3, 4, 5, 6, 7):
            sys.exit("psmpm failed (%d) for %s %s %s" % (code, basis, mass, r))
    text = table(results)
    print(text)
    if args.no_write:
        return
    doc = os.path.join(ROOT, "doc", "chapter.md")
    with open(doc) as f:
        content = f.read()
    begin, end = content.index(BEGIN), content.index(END)
    content = content[:begin + len(BEGIN)] + "\n" + text + content[end:]
    with open(doc, "w") as f:
        f.write(content)
    plot(results, os.path.join(ROOT, "doc", "images", "chapter_bar_large.png"))


if __name__ == "__main__":
    main()
