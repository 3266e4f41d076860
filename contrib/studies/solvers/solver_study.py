#!/usr/bin/python3
"""The mass-matrix solver study beside Wobbes et al. 2019, Tables 4.2-4.4.

  /usr/bin/python3 contrib/studies/solvers/solver_study.py [solver_study.tsv]

Without an argument, runs build/psmpm prm/solver_study.prm (a few minutes)
into a temporary directory first. Copies the table to
doc/data/solver_study.tsv and prints the Markdown tables of
doc/solver_study.md: our value, the chapter's and the deviation in percent.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.environ.get("PSMPM_BINARY", os.path.join(ROOT, "build", "psmpm"))

# The chapter's tables: {p: {1/h: value}}.
TABLE_4_2 = {1: {8: 7.38, 16: 8.55, 32: 8.89, 64: 8.97},
             2: {8: 52.1, 16: 55.1, 32: 56.0, 64: 56.2},
             3: {8: 440, 16: 424, 32: 420, 64: 422},
             4: {8: 3770, 16: 3360, 32: 3290, 64: 3300},
             5: {8: 33000, 16: 26100, 32: 25200, 64: 25200}}
TABLE_4_3 = {1: {16: 18, 32: 18, 64: 18, 128: 17},
             2: {16: 34, 32: 46, 64: 46, 128: 44},
             3: {16: 68, 32: 93, 64: 95, 128: 91},
             4: {16: 93, 32: 178, 64: 196, 128: 187},
             5: {16: 156, 32: 242, 64: 252, 128: 227}}
TABLE_4_4 = {1: {8: 1, 16: 1, 32: 1, 64: 1},
             2: {8: 4, 16: 4, 32: 4, 64: 3},
             3: {8: 15, 16: 12, 32: 10, 64: 9},
             4: {8: 22, 16: 17, 32: 13, 64: 11},
             5: {8: 58, 16: 38, 32: 27, 64: 20}}


def load(path):
    with open(path) as f:
        return list(csv.DictReader(f, delimiter="\t"))


def value(rows, matrix, column, p, n):
    for r in rows:
        if (r["matrix"] == matrix and int(r["degree"]) == p
                and int(r["inverse_h"]) == n):
            v = r[column]
            return None if v == "-" else float(v)
    return None


def table(rows, title, reference, matrix, column, fmt):
    hs = sorted(next(iter(reference.values())).keys())
    print(f"\n{title} ({matrix}, {column}): ours / chapter (deviation)\n")
    print("| p \\ 1/h | " + " | ".join(str(n) for n in hs) + " |")
    print("| --- |" + " --- |" * len(hs))
    for p in sorted(reference):
        cells = []
        for n in hs:
            ours, ref = value(rows, matrix, column, p, n), reference[p][n]
            if ours is None:
                cells.append(f"- / {fmt(ref)}")
            else:
                cells.append(f"{fmt(ours)} / {fmt(ref)} "
                             f"({100 * (ours - ref) / ref:+.0f} %)")
        print(f"| {p} | " + " | ".join(cells) + " |")


def main():
    if len(sys.argv) > 1:
        tsv = sys.argv[1]
    else:
        out = tempfile.mkdtemp(prefix="psmpm-solver-study-")
        subprocess.run([BIN, os.path.join(ROOT, "prm", "solver_study.prm"),
                        "--set", f"Output directory={out}"], check=True,
                       stdout=subprocess.DEVNULL)
        tsv = os.path.join(out, "solver_study.tsv")
    data = os.path.join(ROOT, "doc", "data", "solver_study.tsv")
    if os.path.abspath(tsv) != os.path.abspath(data):
        shutil.copyfile(tsv, data)
    rows = load(tsv)
    sci = lambda x: f"{x:.3g}"
    integer = lambda x: f"{x:.0f}"
    table(rows, "Table 4.2", TABLE_4_2, "bspline dirichlet",
          "condition_number", sci)
    for matrix in ("bspline dirichlet", "bspline free"):
        table(rows, "Table 4.3", TABLE_4_3, matrix, "cg_iterations", integer)
    for matrix in ("bspline dirichlet", "bspline free"):
        table(rows, "Table 4.4", TABLE_4_4, matrix, "pmg_vcycles", integer)


if __name__ == "__main__":
    main()
