#!/usr/bin/python3
"""Run psmpm over a series of parameter overrides and tabulate summary.json.

  contrib/tools/run_series.py --prm prm/vibrating_bar_small.prm \
      --vary "Mesh/Blocks x=4,8,16,32" [--set "Basis/Type=linear"]... \
      [--error errors.displacement_L2] [--out doc/data/table.tsv] [--np N]

Prints a TSV table (value of the varied entry, n_dofs, n_particles, the
error, its rate log2(e_prev/e), wall time, steps, status) and writes it to
--out. A benchmark that reports, not a test: it never fails on numbers.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--prm", required=True)
    ap.add_argument("--vary", required=True, help='"Subsection/Entry=v1,v2,..."')
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--error", default="errors.displacement_L2")
    ap.add_argument("--out")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--binary", default=os.environ.get(
        "PSMPM_BINARY", os.path.join(ROOT, "build", "psmpm")))
    args = ap.parse_args()

    entry, values = args.vary.split("=", 1)
    rows = []
    prev = None
    for v in values.split(","):
        outdir = tempfile.mkdtemp(prefix="psmpm-series-")
        cmd = ([] if args.np == 1 else ["mpirun", "-np", str(args.np)])
        cmd += [args.binary, args.prm, "--set", f"{entry}={v}",
                "--set", f"Output directory={outdir}", "--set", "Output/Interval=0"]
        for s in args.set:
            cmd += ["--set", s]
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT)
        with open(os.path.join(outdir, "summary.json")) as f:
            s = json.load(f)
        group, _, key = args.error.partition(".")
        err = s.get(group, {}).get(key) if key else s.get(group)
        rate = (math.log2(prev / err) if prev and err else float("nan"))
        prev = err
        rows.append([v, s["n_dofs"], s["n_particles"], err, rate,
                     s["wall_time_s"], s["steps"], s["status"]])
    header = [entry, "n_dofs", "n_particles", args.error, "rate",
              "wall_time_s", "steps", "status"]
    lines = ["\t".join(header)]
    for r in rows:
        lines.append("\t".join([str(r[0]), str(r[1]), str(r[2]),
                                f"{r[3]:.5e}" if r[3] is not None else "nan",
                                f"{r[4]:.3f}", f"{r[5]:.3f}", str(r[6]), r[7]]))
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if args.out:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
