#!/usr/bin/python3
"""Largest stable time step of P1 and Powell-Sabin MPM, consistent and
lumped mass, found by bisection on the Courant number (vibrating bar,
8 criss-cross blocks, 8 x 6 particles per block, 400 steps; a run counts
as stable when it completes without tripping a stability monitor).
Every run takes the fixed step Time/Time step = C h_min/c_p, so the
Courant number C is relative to h_min/c_p itself (not to the automatic
step C f h_min/c_p with its per-basis factor f). MUSL throughout, plus
Powell-Sabin with lumped mass and APIC (its automatic transfer).
Compared with the CFL estimate of thesis eq. 2.48, dt = h / sqrt(E/rho).
Writes doc/data/stability_limits.tsv. Reports; never fails on numbers.
"""
import json
import os
import shutil
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.environ.get("PSMPM_BINARY", os.path.join(ROOT, "build", "psmpm"))
BASE = ["Mesh/Blocks x=8", "Particles/Per block x=8", "Particles/Per block y=6",
        "Reference solution/Type=none", "Time/Check stability bound=false",
        "Output/Interval=0"]
# f of P1 with lumped mass (Linear<2>::stability_factor, source/basis/linear.cc):
# the automatic step at Courant number 1 is f h_min/c_p.
P1_LUMPED_FACTOR = 1.5
CASES = [("linear", "consistent", "musl"), ("linear", "lumped", "musl"),
         ("powell-sabin", "consistent", "musl"), ("powell-sabin", "lumped", "musl"),
         ("powell-sabin", "lumped", "apic")]


def run(sets):
    out = tempfile.mkdtemp(prefix="psmpm-stab-")
    cmd = [BIN, "--set", f"Output directory={out}"]
    for s in BASE + sets:
        cmd += ["--set", s]
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    shutil.rmtree(out, ignore_errors=True)
    return summary


def stable(basis, mass, transfer, courant, bound):
    dt = courant * bound
    s = run([f"Basis/Type={basis}", f"Mass matrix/Type={mass}",
             f"Transfer/Scheme={transfer}", f"Time/Time step={dt!r}",
             f"Time/End time={400 * dt!r}"])
    return s["status"] == "completed"


def main():
    # h_min / c_p of this mesh: the first automatic step of lumped P1 at
    # Courant number 1 (particle speeds not yet in it) divided by its f.
    first = run(["Basis/Type=linear", "Mass matrix/Type=lumped", "Time/Time step=0",
                 "Time/Courant number=1", "Time/End time=1e-9"])
    bound = first["time_step_max"] / P1_LUMPED_FACTOR
    c = 10.0  # sqrt(E / rho) = p-wave speed for nu = 0
    h_block = 25 / 8
    print(f"h_min/c_p = {bound:.4e} s", flush=True)
    rows = []
    for basis, mass, transfer in CASES:
        lo, hi = 0.02, 4.0
        for _ in range(12):
            mid = (lo * hi) ** 0.5
            if stable(basis, mass, transfer, mid, bound):
                lo = mid
            else:
                hi = mid
        dt = lo * bound
        rows.append([basis, mass, transfer, f"{lo:.3f}", f"{dt:.4e}",
                     f"{dt / (h_block / c):.3f}"])
        print("\t".join(rows[-1]), flush=True)
    os.makedirs(os.path.join(ROOT, "doc", "data"), exist_ok=True)
    with open(os.path.join(ROOT, "doc", "data", "stability_limits.tsv"), "w") as f:
        f.write(f"# h_min/c_p = {bound:.4e} s; eq. 2.48 with h = block width 25/8: "
                f"{h_block / c:.4e} s; fixed step Time/Time step = C h_min/c_p\n")
        f.write("basis\tmass\ttransfer\tcourant_crit(h_min/c_p)\tdt_crit\t"
                "dt_crit/(h_block/c)\n")
        for r in rows:
            f.write("\t".join(r) + "\n")


if __name__ == "__main__":
    main()
