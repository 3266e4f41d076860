#!/usr/bin/python3
"""Mass matrix strategies on the thesis' failing Powell-Sabin cases, with
the stable coarse runs and P1 on the same grids for comparison, every
run with the thesis' transfer (MUSL; `automatic` would pick apic for
Powell-Sabin's lumped mass on these open-topped scenes).

  /usr/bin/python3 contrib/studies/stability/mass_strategies.py

For each run: completion, exit code, errors against the series or ULFEM
reference (end time, maximum and RMS over time, tracked velocity RMS),
energy drift (largest rise of kinetic + strain + gravitational energy above
its initial value, relative to the largest energy seen), the largest CG
condition estimate, the smallest relative diagonal, DoFs treated and wall
time. Writes doc/data/mass_strategies.tsv. Reports; never fails.
"""
import json
import os
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BIN = os.environ.get("PSMPM_BINARY", os.path.join(ROOT, "build", "psmpm"))
STRATEGIES = ["consistent", "lumped", "partially lumped", "extrapolate",
              "ghost penalty"]


def run(prm, sets):
    out = tempfile.mkdtemp(prefix="psmpm-mass-")
    cmd = [BIN, os.path.join(ROOT, "prm", prm), "--set", f"Output directory={out}",
           "--set", "Output/Interval=0", "--set", "Transfer/Scheme=musl"]
    for s in sets:
        cmd += ["--set", s]
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    s = json.load(open(os.path.join(out, "summary.json")))
    cols, rows = [], []
    for line in open(os.path.join(out, "statistics.txt")):
        if line.startswith("#"):
            cols.append(line.split(":", 1)[1].strip())
        else:
            rows.append(line.split())
    col = {c: i for i, c in enumerate(cols)}

    def series(name):
        return [float(r[col[name]]) for r in rows if r[col[name]] != "-"]

    k, w, g = series("kinetic_energy"), series("strain_energy"), series("gravity_energy")
    total = [a + b + c for a, b, c in zip(k, w, g)]
    scale = max(max(a + b + abs(c) for a, b, c in zip(k, w, g)), 1e-300)
    s["energy_rise"] = max(t - total[0] for t in total) / scale
    s["condition_max"] = max(series("condition_number") or [0])
    s["min_relative_diagonal"] = min([x for x in series("min_relative_diagonal") if x > 0] or [0])
    s["treated_max"] = max(series("treated_dofs") or [0])
    s["exit_code"] = p.returncode
    return s


def main():
    cases = [
        ("column small PS 1x8 (thesis stable)", "soil_column_small.prm", [], ["consistent"]),
        ("column small PS 2x16, dt 1e-3", "soil_column_small.prm",
         ["Mesh/Blocks x=2", "Mesh/Blocks y=16"], STRATEGIES),
        ("column small PS 2x16, dt 5e-4", "soil_column_small.prm",
         ["Mesh/Blocks x=2", "Mesh/Blocks y=16", "Time/Time step=5e-4"], ["consistent"]),
        ("column small P1 2x16", "soil_column_small.prm",
         ["Basis/Type=linear", "Mesh/Blocks x=2", "Mesh/Blocks y=16"], ["lumped", "consistent"]),
        ("column large PS 1x4 (thesis stable)", "soil_column_large.prm", [], ["consistent"]),
        ("column large PS 1x8", "soil_column_large.prm", ["Mesh/Blocks y=8"], STRATEGIES),
        ("column large P1 1x8", "soil_column_large.prm",
         ["Basis/Type=linear", "Mesh/Blocks y=8"], ["lumped", "consistent"]),
        ("column large PS 2x16", "soil_column_large.prm",
         ["Mesh/Blocks x=2", "Mesh/Blocks y=16"], STRATEGIES),
        ("column large P1 2x16", "soil_column_large.prm",
         ["Basis/Type=linear", "Mesh/Blocks x=2", "Mesh/Blocks y=16"], ["lumped", "consistent"]),
        ("bar small PS 8 blocks", "vibrating_bar_small_ps.prm", ["Mesh/Blocks x=8"],
         ["consistent", "partially lumped", "extrapolate", "lumped"]),
    ]
    header = ["case", "mass", "status", "exit", "failed_step", "E_u_end", "E_u_max",
              "E_u_rms_time", "tracked_v_rms", "energy_rise", "cond_max", "min_rel_diag",
              "treated_max", "wall_s"]
    lines = ["\t".join(header)]
    for name, prm, sets, strategies in cases:
        for m in strategies:
            s = run(prm, sets + [f"Mass matrix/Type={m}"])
            e = s.get("errors", {})

            def f(x):
                return "nan" if x is None else f"{x:.3e}"
            r = [name, m, s["status"], str(s["exit_code"]), str(s.get("failed_step", "")),
                 f(e.get("displacement_L2")), f(e.get("displacement_L2_max_over_time")),
                 f(e.get("displacement_L2_rms_over_time")), f(e.get("tracked_velocity_rms")),
                 f"{s['energy_rise']:.3f}", f"{s['condition_max']:.2e}",
                 f"{s['min_relative_diagonal']:.2e}", str(int(s["treated_max"])),
                 f"{s['wall_time_s']:.2f}"]
            lines.append("\t".join(r))
            print(lines[-1], flush=True)
    os.makedirs(os.path.join(ROOT, "doc", "data"), exist_ok=True)
    with open(os.path.join(ROOT, "doc", "data", "mass_strategies.tsv"), "w") as fh:
        fh.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
