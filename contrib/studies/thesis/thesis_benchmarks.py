#!/usr/bin/python3
"""Thesis chapter 4 benchmarks, P1 and Powell-Sabin, in one run on this
machine: tables (TSV) in doc/data/, plots (PNG) in doc/images/, and a
summary of the figures quoted in doc/benchmarks.md on stdout.

  /usr/bin/python3 contrib/studies/thesis/thesis_benchmarks.py [--only bar_small,...]

A benchmark that reports; it never fails on numbers. Parts: bar_small,
column_small, bar_large, column_large, unstable.
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.environ.get("PSMPM_BINARY", os.path.join(ROOT, "build", "psmpm"))
DATA = os.path.join(ROOT, "doc", "data")
IMAGES = os.path.join(ROOT, "doc", "images")


def run(prm, sets):
    out = tempfile.mkdtemp(prefix="psmpm-bench-")
    cmd = [BIN, os.path.join(ROOT, "prm", prm), "--set", f"Output directory={out}"]
    for s in sets:
        cmd += ["--set", s]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    s["exit_code"] = proc.returncode
    s["dir"] = out
    return s


def history(summary):
    path = os.path.join(summary["dir"], "tracked_particle.txt")
    rows = [list(map(float, l.split())) for l in open(path) if not l.startswith("#")]
    return [list(c) for c in zip(*rows)]


def write_tsv(name, header, rows):
    os.makedirs(DATA, exist_ok=True)
    with open(os.path.join(DATA, name), "w") as f:
        f.write("\t".join(header) + "\n")
        for r in rows:
            f.write("\t".join(str(x) for x in r) + "\n")


def fmt(x):
    return f"{x:.4e}" if isinstance(x, float) else str(x)


def bar_small():
    thesis_p1 = {4: 1.80956e-4, 8: 4.44076e-5, 16: 1.07531e-5, 32: 2.68352e-6}
    thesis_ps = {1: 3.70985e-4, 2: 3.13639e-5, 4: 3.56528e-6, 8: 4.90397e-7, 16: 1.76596e-7}
    rows, series = [], {"linear": [], "powell-sabin": []}
    runs = [("linear", b, 16, 14) for b in (4, 8, 16, 32)] + \
           [("powell-sabin", b, 16, 14) for b in (1, 2, 4, 8, 16)] + \
           [("powell-sabin", 16, 20, 18)]
    for basis, b, px, py in runs:
        s = run("vibrating_bar_small.prm", [f"Basis/Type={basis}", f"Mesh/Blocks x={b}",
                                            f"Particles/Per block x={px}",
                                            f"Particles/Per block y={py}", "Output/Interval=0"])
        e = s["errors"]["displacement_L2"]
        ref = (thesis_p1 if basis == "linear" else thesis_ps).get(b) if px == 16 else 1.14682e-7
        rows.append([basis, b, px * py // 4, s["n_dofs"], fmt(e), fmt(ref), f"{e / ref:.3f}",
                     f"{s['wall_time_s']:.3f}", f"{s['time_loop_s']:.3f}"])
        if px == 16:
            series[basis].append((b, e, s["wall_time_s"], s["n_dofs"]))
    for basis in series:
        pts = series[basis]
        for i in range(1, len(pts)):
            rows[[r[0] for r in rows].index(basis) + i].append(
                f"{math.log2(pts[i - 1][1] / pts[i][1]):.3f}")
    write_tsv("vibrating_bar_small.tsv",
              ["basis", "blocks_x", "particles_per_element", "n_dofs", "E_u", "thesis",
               "ratio", "wall_time_s", "time_loop_s", "rate"], rows)

    # Error against run time: PS time to reach P1's 32-block error, by
    # log-log interpolation between the PS runs that bracket it.
    p1_err, p1_time = series["linear"][-1][1], series["linear"][-1][2]
    ps = series["powell-sabin"]
    ratio = float("nan")
    for (b0, e0, t0, _), (b1, e1, t1, _) in zip(ps, ps[1:]):
        if e0 >= p1_err >= e1:
            w = math.log(e0 / p1_err) / math.log(e0 / e1)
            t = math.exp((1 - w) * math.log(t0) + w * math.log(t1))
            ratio = t / p1_time
            print(f"bar_small: PS reaches P1-32 error {p1_err:.3e} in {t:.3f} s "
                  f"(between {b0} and {b1} blocks); P1-32 takes {p1_time:.3f} s; ratio {ratio:.3f}")
    write_tsv("error_vs_time_ratio.tsv", ["p1_32_error", "p1_32_wall_s", "ps_wall_s_at_that_error", "ratio"],
              [[fmt(p1_err), f"{p1_time:.3f}", f"{ratio * p1_time:.3f}", f"{ratio:.3f}"]])

    os.makedirs(IMAGES, exist_ok=True)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for basis, mark in (("linear", "o-"), ("powell-sabin", "s-")):
        pts = series[basis]
        ax[0].loglog([25 / b for b, *_ in pts], [e for _, e, *_ in pts], mark, label=basis)
        ax[1].loglog([t for *_, t, _ in pts], [e for _, e, *_ in pts], mark, label=basis)
    h = [25 / b for b in (1, 2, 4, 8)]
    ax[0].loglog(h, [3e-4 * (x / 25) ** 3 for x in h], "k:", label="h^3")
    ax[0].loglog(h, [1.2e-2 * (x / 25) ** 2 for x in h], "k--", label="h^2")
    ax[0].set_xlabel("block width h [m]"); ax[0].set_ylabel("E_u at t = 0.02")
    ax[1].set_xlabel("wall time [s]"); ax[1].set_ylabel("E_u at t = 0.02")
    for a in ax:
        a.grid(True, which="both", alpha=0.3); a.legend()
    fig.suptitle("Vibrating bar, small deformation (thesis Tables 4.2, 4.3)")
    fig.tight_layout(); fig.savefig(os.path.join(IMAGES, "vibrating_bar_small.png"), dpi=110)
    print("bar_small:", *["\t".join(map(str, r)) for r in rows], sep="\n")


def velocity_plot(name, title, runs, ylabel="velocity [m/s]"):
    fig, ax = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for label, s in runs:
        t, u, v, ur, vr = history(s)
        ax[0].plot(t, u, label=label); ax[1].plot(t, v, label=label)
    ax[0].plot(t, ur, "k--", label="reference"); ax[1].plot(t, vr, "k--", label="reference")
    ax[0].set_ylabel("displacement [m]"); ax[1].set_ylabel(ylabel); ax[1].set_xlabel("time [s]")
    for a in ax:
        a.grid(True, alpha=0.3); a.legend(fontsize=8)
    fig.suptitle(title); fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, name), dpi=110)


def column_small():
    # The thesis' method: consistent mass.
    ps = run("soil_column_small.prm", ["Output/Interval=0", "Mass matrix/Type=consistent"])
    p1 = run("soil_column_small.prm", ["Basis/Type=linear", "Mesh/Blocks x=2", "Mesh/Blocks y=16",
                                       "Output/Interval=0", "Mass matrix/Type=consistent"])
    rows = []
    for label, s in (("PS 1x8", ps), ("P1 2x16", p1)):
        e = s["errors"]
        rows.append([label, s["n_dofs"], s["status"], fmt(e["tracked_velocity_rms"]),
                     fmt(e["tracked_displacement_rms"]), fmt(e["displacement_L2"]),
                     fmt(e["velocity_L2_rms_over_time"]), f"{s['wall_time_s']:.3f}"])
    ratio = ps["errors"]["tracked_velocity_rms"] / p1["errors"]["tracked_velocity_rms"]
    write_tsv("soil_column_small.tsv", ["run", "n_dofs", "status", "tracked_velocity_rms",
                                        "tracked_displacement_rms", "displacement_L2_end",
                                        "velocity_L2_rms_over_time", "wall_time_s"], rows)
    velocity_plot("soil_column_small.png", "Soil column, small deformation: particle at mid-height",
                  [("P1 2x16", p1), ("PS 1x8", ps)])
    print("column_small:", *["\t".join(map(str, r)) for r in rows], sep="\n")
    print(f"column_small: PS/P1 tracked velocity RMS = {ratio:.3f} (1/{1 / ratio:.1f})")


def bar_large():
    runs = [("PS 8 blocks, 20 ppe", run("vibrating_bar_large.prm", ["Output/Interval=0"])),
            ("P1 16 blocks, 6 ppe", run("vibrating_bar_large.prm", [
                "Basis/Type=linear", "Mesh/Blocks x=16", "Particles/Per block x=6",
                "Particles/Per block y=4", "Output/Interval=0"])),
            ("P1 16 blocks, 56 ppe", run("vibrating_bar_large.prm", [
                "Basis/Type=linear", "Mesh/Blocks x=16", "Particles/Per block x=16",
                "Particles/Per block y=14", "Output/Interval=0"]))]
    rows = [[l, s["n_dofs"], s["status"], fmt(s["errors"]["displacement_L2"]),
             fmt(s["errors"]["displacement_L2_max_over_time"]),
             fmt(s["errors"]["tracked_velocity_rms"]), f"{s['wall_time_s']:.2f}"] for l, s in runs]
    write_tsv("vibrating_bar_large.tsv", ["run", "n_dofs", "status", "displacement_L2_end",
                                          "displacement_L2_max", "tracked_velocity_rms",
                                          "wall_time_s"], rows)
    velocity_plot("vibrating_bar_large.png", "Vibrating bar, large deformation: particle at x = 12.5",
                  runs)
    print("bar_large:", *["\t".join(map(str, r)) for r in rows], sep="\n")


def column_large():
    consistent = "Mass matrix/Type=consistent"  # the thesis' method
    runs = [("PS 1x4", run("soil_column_large.prm", ["Output/Interval=0", consistent])),
            ("P1 1x4", run("soil_column_large.prm", ["Basis/Type=linear", "Output/Interval=0",
                                                     consistent]))]
    rows = [[l, s["n_dofs"], s["status"], fmt(s["errors"]["displacement_L2"]),
             fmt(s["errors"]["displacement_L2_max_over_time"]),
             fmt(s["errors"]["tracked_velocity_rms"]), f"{s['wall_time_s']:.2f}"] for l, s in runs]
    write_tsv("soil_column_large.tsv", ["run", "n_dofs", "status", "displacement_L2_end",
                                        "displacement_L2_max", "tracked_velocity_rms",
                                        "wall_time_s"], rows)
    velocity_plot("soil_column_large.png", "Soil column, large deformation: particle at mid-height",
                  runs)
    print("column_large:", *["\t".join(map(str, r)) for r in rows], sep="\n")


def unstable():
    rows = []
    for label, prm, sets in (
            ("soil column small, PS 2x16", "soil_column_small.prm",
             ["Mesh/Blocks x=2", "Mesh/Blocks y=16"]),
            ("soil column large, PS 1x8", "soil_column_large.prm", ["Mesh/Blocks y=8"])):
        s = run(prm, sets + ["Output/Interval=100", "Mass matrix/Type=consistent"])
        rows.append([label, s["status"], s["exit_code"], s.get("failed_step"),
                     s.get("failed_time"), s.get("reason")])
    write_tsv("unstable_configurations.tsv", ["run", "status", "exit_code", "failed_step",
                                               "failed_time", "reason"], rows)
    print("unstable:", *["\t".join(map(str, r)) for r in rows], sep="\n")


def main():
    parts = ["bar_small", "column_small", "bar_large", "column_large", "unstable"]
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", default=",".join(parts))
    for p in ap.parse_args().only.split(","):
        globals()[p]()


if __name__ == "__main__":
    main()
