#!/usr/bin/python3
"""Convergence of MPM and BSMPM on the vibrating bar of Wobbes et al. 2019
(book chapter, section 4.5, Table 4.1; prm/chapter_bar_1d.prm).

Runs build/psmpm for 5, 10, 20, 40 elements with Basis/Type = linear (MPM,
lumped mass) and bspline (BSMPM, quadratic B-splines, lumped and
consistent mass), MUSL, reads the
RMS errors of displacement, velocity and stress at T = 1.9e-6 s from
summary.json, and writes the table with the observed rates and the CPU
(user + sys of the child, getrusage) and wall seconds of every run into
doc/chapter.md (between the table markers) and a plot into
doc/images/chapter_bar_convergence.png.

    /usr/bin/python3 contrib/studies/chapter/chapter_bar_study.py [--psmpm build/psmpm]
        [--no-write] [--stability] [--degree P [P ...]]

With --stability it instead bisects the largest stable fixed time step of
BSMPM (and MPM for comparison) on the bar of 10 elements, lumped and
consistent mass, with fixed and with free ends (2000 steps; stable: the
run completes without tripping a stability monitor), and prints it over
h / c_p: the measurement behind Basis::BSpline::stability_factor().

With --degree P [P ...] (Basis/Degree of bspline; without it, quadratic
as above and the output is that of the quadratic study) the convergence
study runs BSMPM of each degree P with consistent mass (and lumped mass
for P <= 2, the only degrees that verify it) and writes its table into
doc/chapter.md between the higher-degree markers; --stability bisects
the stable step of BSMPM of each degree P only (consistent mass, and
lumped for P <= 2) after the eigenvalue bound of degree P.

Debian python3 with numpy and matplotlib only.
"""
import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
ELEMENTS = [5, 10, 20, 40]
METHODS = [("MPM", "linear"), ("BSMPM", "bspline")]
# The chapter's MPM and BSMPM (lumped mass, its "standard mapping") and
# BSMPM with consistent mass, psmpm's default for bspline.
CONVERGENCE = [("MPM lumped", "linear", "lumped"),
               ("BSMPM lumped", "bspline", "lumped"),
               ("BSMPM consistent", "bspline", "consistent")]
BEGIN = "<!-- chapter_bar_study table begin -->"
END = "<!-- chapter_bar_study table end -->"
DEGREE_BEGIN = "<!-- chapter_bar_study degree table begin -->"
DEGREE_END = "<!-- chapter_bar_study degree table end -->"
TLS_BEGIN = "<!-- chapter_bar_study tls table begin -->"
TLS_END = "<!-- chapter_bar_study tls table end -->"
# Taylor least squares (--tls): the chapter's fields and the stress alone.
TLS = "Transfer/Reconstruction=taylor least squares"
TLS_CASES = [
    ("TLS-BSMPM lumped (chapter)", "bspline", "lumped",
     [TLS, "Transfer/Taylor least squares/Fields=stress and momentum"]),
    ("TLS-BSMPM consistent (chapter)", "bspline", "consistent",
     [TLS, "Transfer/Taylor least squares/Fields=stress and momentum"]),
    ("TLS-BSMPM consistent, lumped acceleration (chapter exact)", "bspline",
     "consistent",
     [TLS, "Transfer/Taylor least squares/Fields=stress and momentum",
      "Transfer/Taylor least squares/Acceleration mass=lumped"]),
    ("TLS-BSMPM consistent, centred momentum", "bspline", "consistent",
     [TLS, "Transfer/Taylor least squares/Fields=stress and centred momentum"]),
    ("TLS-BSMPM consistent, centred momentum, lumped acceleration", "bspline",
     "consistent",
     [TLS, "Transfer/Taylor least squares/Fields=stress and centred momentum",
      "Transfer/Taylor least squares/Acceleration mass=lumped"]),
    ("TLS-BSMPM consistent, stress", "bspline", "consistent",
     [TLS, "Transfer/Taylor least squares/Fields=stress"])]


def masses(degree):
    """Mass matrices verified with bspline of this degree."""
    return ("lumped", "consistent") if degree <= 2 else ("consistent",)


def run(psmpm, basis, elements, mass, directory, degree=2, extra=()):
    """One run; returns (errors dict, cpu seconds, wall seconds)."""
    out = os.path.join(directory, "%s-%d-%s-%d-%d" % (basis, degree, mass,
                                                      elements, len(extra)))
    command = [psmpm, os.path.join(ROOT, "prm", "chapter_bar_1d.prm"),
               "--set", "Basis/Type=" + basis,
               "--set", "Basis/Degree=%d" % degree,
               "--set", "Mesh/Blocks x=%d" % elements,
               "--set", "Mass matrix/Type=" + mass,
               "--set", "Output directory=" + out]
    for e in extra:
        command += ["--set", e]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        sys.exit("psmpm failed (%d): %s\n%s" % (result.returncode,
                                               " ".join(command),
                                               result.stdout))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    errors = summary["errors"]
    return ({"u": errors["displacement_L2"], "v": errors["velocity_L2"],
             "s": errors["stress_L2"]}, cpu, wall)


def stable(psmpm, basis, mass, fixed, dt, directory, degree=2):
    out = os.path.join(directory, "stability")
    command = [psmpm, os.path.join(ROOT, "prm", "chapter_bar_1d.prm"),
               "--set", "Basis/Type=" + basis,
               "--set", "Basis/Degree=%d" % degree,
               "--set", "Mass matrix/Type=" + mass,
               "--set", "Boundary conditions/Fixed x=" + fixed,
               # Free ends: the free-free mode, which does not drift away.
               "--set", "Initial conditions/Velocity=" +
               ("v0*sin(pi*x/L)" if fixed else "v0*cos(pi*x/L)"),
               "--set", "Reference solution/Type=none",
               "--set", "Time/Check stability bound=false",
               "--set", "Time/Time step=%.17g" % dt,
               "--set", "Time/End time=%.17g" % (2000.5 * dt),
               "--set", "Output directory=" + out]
    result = subprocess.run(command, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    # 3-7: a stability monitor stopped the run (doc: README exit codes).
    if result.returncode not in (0, 3, 4, 5, 6, 7):
        sys.exit("psmpm failed (%d): %s" % (result.returncode,
                                            " ".join(command)))
    return result.returncode == 0


def stability(psmpm, degrees=None):
    """Bisection of dt c_p / h on 10 elements of the chapter bar: MPM and
    quadratic BSMPM, or BSMPM of the given degrees."""
    h_over_c = 0.1 / math.sqrt(7e6 / 2000)
    if degrees is None:
        cases = [(name, basis, 2, mass) for name, basis in METHODS
                 for mass in ("lumped", "consistent")]
    else:
        cases = [("BSMPM p=%d" % p, "bspline", p, mass) for p in degrees
                 for mass in masses(p)]
    print("| method | mass | ends | largest stable dt c_p / h |")
    print("| --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as directory:
        for name, basis, degree, mass in cases:
            for ends, fixed in (("fixed", "left, right"), ("free", "")):
                lo, hi = 0.05, 2.0
                for _ in range(14):
                    mid = 0.5 * (lo + hi)
                    if stable(psmpm, basis, mass, fixed, mid * h_over_c,
                              directory, degree):
                        lo = mid
                    else:
                        hi = mid
                print("| %s | %s | %s | %.3f |" % (name, mass, ends, lo),
                      flush=True)


def bspline_matrices(p, n):
    """Mass and stiffness matrices of the n + p B-splines of degree p on
    the open uniform knot vector of [0, 1] with n elements (Cox-de Boor at
    p + 1 Gauss points per element)."""
    import numpy as np
    t = np.concatenate([np.zeros(p), np.linspace(0, 1, n + 1), np.ones(p)])
    g, w = np.polynomial.legendre.leggauss(p + 1)
    M = np.zeros((n + p, n + p))
    K = np.zeros_like(M)
    for e in range(n):
        mu = e + p
        for gq, wq in zip(g, w):
            x = t[mu] + (gq + 1) / 2 * (t[mu + 1] - t[mu])
            jw = wq / 2 * (t[mu + 1] - t[mu])
            # N[k][r]: B_{mu-k+r, k}(x); derivatives from degree p - 1.
            N = [np.array([1.0])]
            for k in range(1, p + 1):
                prev, cur = N[-1], np.zeros(k + 1)
                for r in range(k + 1):
                    i = mu - k + r
                    if r >= 1:
                        cur[r] += (x - t[i]) / (t[i + k] - t[i]) * prev[r - 1]
                    if r < k:
                        cur[r] += ((t[i + k + 1] - x) /
                                   (t[i + k + 1] - t[i + 1]) * prev[r])
                N.append(cur)
            dN = np.zeros(p + 1)
            for r in range(p + 1):
                i = mu - p + r
                if r >= 1:
                    dN[r] += p / (t[i + p] - t[i]) * N[p - 1][r - 1]
                if r < p:
                    dN[r] -= p / (t[i + p + 1] - t[i + 1]) * N[p - 1][r]
            d = slice(mu - p, mu + 1)
            M[d, d] += jw * np.outer(N[p], N[p])
            K[d, d] += jw * np.outer(dN, dN)
    return M, K


def eigenvalue_bound(p=2, n=40):
    """2 / omega_max over h / c of the exact B-spline system of degree p
    on n elements of the bar, lumped (row sums of the B-splines' mass
    matrix; p <= 2 only, the degrees that verify it) and consistent mass,
    fixed and free ends: the linear stability limit of central
    differences without particle quadrature."""
    import numpy as np
    h = 1.0 / n
    M, K = bspline_matrices(p, n)
    print("| mass | ends | 2 / omega_max over h / c |")
    print("| --- | --- | --- |")
    for mass in masses(p):
        for ends in ("fixed", "free"):
            m, k = (M[1:-1, 1:-1], K[1:-1, 1:-1]) if ends == "fixed" else (M, K)
            if mass == "lumped":
                m = np.diag(m.sum(axis=1))
            lam = max(np.linalg.eigvals(np.linalg.solve(m, k)).real)
            print("| %s | %s | %.3f |" % (mass, ends, 2 / math.sqrt(lam) / h))


def rate(e_coarse, e_fine):
    return math.log2(e_coarse / e_fine)


def table(results, names):
    lines = ["| method | elements | u RMS error | rate | v RMS error | rate "
             "| stress RMS error | rate | CPU s | wall s |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for name in names:
        rows = results[name]
        for i, n in enumerate(ELEMENTS):
            e, cpu, wall = rows[i]
            cells = [name, str(n)]
            for q in "uvs":
                cells.append("%.3e" % e[q])
                cells.append("-" if i == 0 else
                             "%.2f" % rate(rows[i - 1][0][q], e[q]))
            cells += ["%.2f" % cpu, "%.2f" % wall]
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8))
    for ax, q, title in zip(axes, "uvs",
                            ["displacement", "velocity", "stress"]):
        for (name, _, _), marker in zip(CONVERGENCE, "os^"):
            ax.loglog(ELEMENTS, [r[0][q] for r in results[name]],
                      marker + "-", label=name)
        ax.set_xticks(ELEMENTS)
        ax.set_xticklabels([str(n) for n in ELEMENTS])
        ax.minorticks_off()
        ax.set_xlabel("elements")
        ax.set_title(title + " RMS error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--psmpm", default=os.path.join(ROOT, "build",
                                                        "psmpm"))
    parser.add_argument("--no-write", action="store_true",
                        help="print the table only")
    parser.add_argument("--stability", action="store_true",
                        help="bisect the stable time step instead")
    parser.add_argument("--tls", action="store_true",
                        help="Taylor least squares (TLS-BSMPM) instead")
    parser.add_argument("--degree", type=int, nargs="+",
                        help="Basis/Degree of BSMPM (default: the "
                        "quadratic study with MPM)")
    args = parser.parse_args()
    if args.stability:
        for p in args.degree or [2]:
            eigenvalue_bound(p)
        stability(args.psmpm, args.degree)
        return
    if args.tls:
        cases = [(name, basis, mass, 2, extra)
                 for name, basis, mass, extra in TLS_CASES]
        begin_marker, end_marker = TLS_BEGIN, TLS_END
    elif args.degree:
        cases = [("BSMPM p=%d %s" % (p, mass), "bspline", mass, p, ())
                 for p in args.degree for mass in masses(p)]
        begin_marker, end_marker = DEGREE_BEGIN, DEGREE_END
    else:
        cases = [(name, basis, mass, 2, ())
                 for name, basis, mass in CONVERGENCE]
        begin_marker, end_marker = BEGIN, END
    results = {}
    with tempfile.TemporaryDirectory() as directory:
        for name, basis, mass, degree, extra in cases:
            results[name] = [run(args.psmpm, basis, n, mass, directory,
                                 degree, extra)
                             for n in ELEMENTS]
    text = table(results, [case[0] for case in cases])
    print(text)
    if args.no_write:
        return
    doc = os.path.join(ROOT, "doc", "chapter.md")
    with open(doc) as f:
        content = f.read()
    begin, end = content.index(begin_marker), content.index(end_marker)
    content = (content[:begin + len(begin_marker)] + "\n" + text +
               content[end:])
    with open(doc, "w") as f:
        f.write(content)
    if not args.degree and not args.tls:
        plot(results, os.path.join(ROOT, "doc", "images",
                                   "chapter_bar_convergence.png"))


if __name__ == "__main__":
    main()
