#!/usr/bin/python3
"""Largest stable time step of P1 and Powell-Sabin MPM, consistent and
lumped mass, found by bisection on the Courant number (vibrating bar,
8 criss-cross blocks, 8 x 6 particles per block, 400 steps; a run counts
as stable when it completes without tripping a stability monitor).
Compared with the CFL estimate of thesis eq. 2.48, dt = h / sqrt(E/rho).
Writes doc/data/stability_limits.tsv. Reports; never fails on numbers.
"""
import json
import os
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.environ.get("PSMPM_BINARY", os.path.join(ROOT, "build", "psmpm"))
BASE = ["Mesh/Blocks x=8", "Particles/Per block x=8", "Particles/Per block y=6",
        "Reference solution/Type=none", "Time/Time step=0",
        "Time/Check stability bound=false", "Output/Interval=0"]


def run(sets):
    out = tempfile.mkdtemp(prefix="psmpm-stab-")
    cmd = [BIN, "--set", f"Output directory={out}"]
    for s in BASE + sets:
        cmd += ["--set", s]
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def stable(basis, mass, courant, bound):
    dt = courant * bound
    s = run([f"Basis/Type={basis}", f"Mass matrix/Type={mass}",
             f"Time/Courant number={courant}", f"Time/End time={400 * dt}"])
    return s["status"] == "completed"


def main():
    # h_min / c_p of this mesh: the automatic step at Courant number 1.
    bound = run(["Time/Courant number=1", "Time/End time=1e-9"])["time_step"]
    c = 10.0  # sqrt(E / rho) = p-wave speed for nu = 0
    h_block = 25 / 8
    rows = []
    for basis in ("linear", "powell-sabin"):
        for mass in ("consistent", "lumped"):
            lo, hi = 0.02, 4.0
            for _ in range(12):
                mid = (lo * hi) ** 0.5
                if stable(basis, mass, mid, bound):
                    lo = mid
                else:
                    hi = mid
            dt = lo * bound
            rows.append([basis, mass, f"{lo:.3f}", f"{dt:.4e}", f"{dt / (h_block / c):.3f}"])
            print("\t".join(rows[-1]), flush=True)
    os.makedirs(os.path.join(ROOT, "doc", "data"), exist_ok=True)
    with open(os.path.join(ROOT, "doc", "data", "stability_limits.tsv"), "w") as f:
        f.write(f"# h_min/c_p = {bound:.4e} s; eq. 2.48 with h = block width 25/8: "
                f"{h_block / c:.4e} s\n")
        f.write("basis\tmass\tcourant_crit(h_min/c_p)\tdt_crit\tdt_crit/(h_block/c)\n")
        for r in rows:
            f.write("\t".join(r) + "\n")


if __name__ == "__main__":
    main()
